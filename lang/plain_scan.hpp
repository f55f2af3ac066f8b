// Internal to lang/: the lexical pieces the hand readers (plain_solid_item.cpp, plain_expression.cpp)
// share, each the exact twin of a grammar.hpp rule named beside it. A reader that finds anything else
// declines, and the grammar reads the text again.
#pragma once

#include <charconv>
#include <string_view>
#include <system_error>

namespace hlr::lang::scan {

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_first(char c) {  // identifier_first
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
inline bool is_other(char c) { return is_first(c) || is_digit(c); }  // identifier_other

// sp: blanks and `#` comments. A comment runs to the end of its line (until< eolf >): a lone '\r'
// belongs to it, "\r\n" and "\n" end it, and the newline is a blank anyway.
inline const char* skip_padding(const char* p, const char* end) {
  while (p < end) {
    const char c = *p;
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
      ++p;
    } else if (c == '#') {
      while (p < end && *p != '\n') ++p;
    } else {
      break;
    }
  }
  return p;
}

// The whole identifier at p (identifier), or empty.
inline std::string_view word_at(const char* p, const char* end) {
  if (p >= end || !is_first(*p)) return {};
  const char* q = p + 1;
  while (q < end && is_other(*q)) ++q;
  return {p, static_cast<std::size_t>(q - p)};
}

// number (with a leading '-' when `signed_number`, as literal_number), then the `must` checks after
// it (number_single_point, number_no_letter). False where the grammar fails or raises an error, out of
// range included.
inline bool read_number(const char*& p, const char* end, double& value, bool signed_number) {
  const char* q = p;
  if (signed_number && q < end && *q == '-') ++q;
  if (q >= end || !is_digit(*q)) return false;
  while (q < end && is_digit(*q)) ++q;
  if (q + 1 < end && *q == '.' && is_digit(q[1])) {
    q += 2;
    while (q < end && is_digit(*q)) ++q;
  }
  if (q < end && (*q == 'e' || *q == 'E')) {
    ++q;
    if (q < end && (*q == '+' || *q == '-')) ++q;
    if (q >= end || !is_digit(*q)) return false;  // the grammar's error (exponent_digits)
    while (q < end && is_digit(*q)) ++q;
  }
  if (q < end && (is_other(*q) || (*q == '.' && q + 1 < end && is_digit(q[1])))) return false;
  const auto result = std::from_chars(p, q, value);
  if (result.ec != std::errc() || result.ptr != q) return false;  // out of range: the grammar's error
  p = q;
  return true;
}

}  // namespace hlr::lang::scan
