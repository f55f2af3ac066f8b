#include "core/device/formats/json_text.hpp"

#include <charconv>
#include <cstring>

#include "core/device/page/utf8.hpp"

namespace hlr {

void append_json_number(std::string& out, double v) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, v);
  (void)error;  // 32 bytes hold any double's shortest form (at most 24 characters)
  out.append(buffer, end);
  if (std::memchr(buffer, '.', static_cast<std::size_t>(end - buffer)) == nullptr &&
      std::memchr(buffer, 'e', static_cast<std::size_t>(end - buffer)) == nullptr)
    out += ".0";
}

void append_json_integer(std::string& out, long long v) {
  char buffer[24];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, v);
  (void)error;
  out.append(buffer, end);
}

bool append_json_string(std::string& out, std::string_view s) {
  static constexpr char kHex[] = "0123456789abcdef";
  out += '"';
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20) {
      switch (c) {
        case '\n':
          out += "\\n";
          break;
        case '\t':
          out += "\\t";
          break;
        case '\r':
          out += "\\r";
          break;
        case '\b':
          out += "\\b";
          break;
        case '\f':
          out += "\\f";
          break;
        default:
          out += "\\u00";
          out += kHex[c >> 4];
          out += kHex[c & 0xf];
      }
    } else if (c < 0x80) {
      out += static_cast<char>(c);
    } else {
      const std::size_t n = utf8_sequence_length(s, i);
      if (n == 0) return false;
      out.append(s, i, n);
      i += n;
      continue;
    }
    ++i;
  }
  out += '"';
  return true;
}

}  // namespace hlr
