// Every test here mirrors a rule of grammar.hpp (named in the comments); where the grammar would raise an
// error or take a form this reader does not, it declines and the grammar reads the item again.
#include "lang/plain_solid_item.hpp"

#include <array>
#include <charconv>
#include <cstdint>
#include <deque>
#include <string_view>
#include <system_error>
#include <vector>

#include "lang/grammar.hpp"
#include "lang/plain_scan.hpp"

namespace hlr::lang {

namespace {

namespace g = grammar;

using scan::is_digit;
using scan::is_other;
using scan::skip_padding;
using scan::word_at;

bool is_keyword(std::string_view w) { return g::reserved::contains(w) || g::solid_words::contains(w); }

enum class Read { Yes, No, Decline };

// A vertex id (vertex_id): digits not followed by a letter (id_number), or a name that is neither
// reserved nor a solid word (id_name). `key` gets its key as SolidBody::intern wants it.
Read read_id(const char*& p, const char* end, std::string_view& key, std::array<char, 24>& digits) {
  if (p < end && is_digit(*p)) {
    const char* q = p;
    while (q < end && is_digit(*q)) ++q;
    if (q < end && is_other(*q)) return Read::No;
    const std::string_view text(p, static_cast<std::size_t>(q - p));
    if (text.size() == 1 || (text[0] != '0' && text.size() < 19)) {
      key = text;  // already its value in decimal, and below 2^63
    } else {
      std::int64_t number = 0;
      if (std::from_chars(text.data(), text.data() + text.size(), number).ec != std::errc())
        return Read::Decline;
      const auto printed = std::to_chars(digits.data(), digits.data() + digits.size(), number);
      key = std::string_view(digits.data(), static_cast<std::size_t>(printed.ptr - digits.data()));
    }
    p = q;
    return Read::Yes;
  }
  const std::string_view w = word_at(p, end);
  if (w.empty() || is_keyword(w)) return Read::No;
  key = w;
  p += w.size();
  return Read::Yes;
}

// literal_number and the checks after it.
bool read_number(const char*& p, const char* end, double& value) {
  return scan::read_number(p, end, value, /*signed_number=*/true);
}

const char* skip_blanks(const char* p, const char* end) {  // literal_blanks
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  return p;
}

// literal_position: "(" n "," n "," n ")" with blanks, then at< sp, vertex | face | line | "}" >.
bool read_position(const char*& p, const char* end, std::array<double, 3>& xyz) {
  const char* q = p;
  if (q >= end || *q != '(') return false;
  ++q;
  for (std::size_t i = 0; i < 3; ++i) {
    q = skip_blanks(q, end);
    if (!read_number(q, end, xyz[i])) return false;
    q = skip_blanks(q, end);
    if (q >= end || *q != (i < 2 ? ',' : ')')) return false;
    ++q;
  }
  const char* next = skip_padding(q, end);
  if (next < end && *next == '}') {
    p = q;
    return true;
  }
  const std::string_view w = word_at(next, end);
  if (w != "vertex" && w != "face" && w != "line") return false;
  p = q;
  return true;
}

// Keys of the ids of the item being read, interned only once the whole item has been read.
struct Keys {
  std::vector<std::string_view> keys;
  std::deque<std::array<char, 24>> digits;  // where renumbered keys ("007" → "7") live; never moved
  std::size_t renumbered = 0;

  Read read(const char*& p, const char* end) {
    if (renumbered == digits.size()) digits.emplace_back();
    std::string_view key;
    const Read r = read_id(p, end, key, digits[renumbered]);
    if (r != Read::Yes) return r;
    if (key.data() == digits[renumbered].data()) ++renumbered;
    keys.push_back(key);
    return r;
  }
};

}  // namespace

std::size_t read_plain_solid_item(const char* base, const char* at, const char* end, SolidBody& body) {
  const std::string_view keyword = word_at(at, end);
  const bool vertex = keyword == "vertex", face = keyword == "face", line = keyword == "line";
  if (!vertex && !face && !line) return 0;
  const char* p = skip_padding(at + keyword.size(), end);

  thread_local Keys ids;
  ids.keys.clear();
  ids.renumbered = 0;
  if (ids.read(p, end) != Read::Yes) return 0;
  std::array<double, 3> xyz{};
  if (vertex) {  // vertex_decl: vertex ID = POSITION
    p = skip_padding(p, end);
    if (p >= end || *p != '=' || (p + 1 < end && p[1] == '=')) return 0;
    p = skip_padding(p + 1, end);
    if (!read_position(p, end, xyz)) return 0;
  } else if (face) {  // face_decl: face ID (sp ID)*, and no hole clause
    for (;;) {
      const char* q = skip_padding(p, end);
      const Read r = ids.read(q, end);
      if (r == Read::Decline) return 0;
      if (r == Read::No) {
        if (word_at(q, end) == "hole") return 0;
        break;
      }
      p = q;
    }
  } else {  // line_decl: line ID sp ID
    p = skip_padding(p, end);
    if (ids.read(p, end) != Read::Yes) return 0;
  }

  const auto begin = static_cast<std::uint32_t>(at - base), finish = static_cast<std::uint32_t>(p - base);
  thread_local std::vector<std::uint32_t> refs;
  refs.clear();
  for (const std::string_view key : ids.keys) refs.push_back(body.intern(key));
  if (vertex) {
    body.add_vertex(refs[0], xyz, begin, finish);
  } else if (face) {
    const std::uint32_t ring_end = static_cast<std::uint32_t>(refs.size());
    body.add_face(refs, {&ring_end, 1}, begin, finish);
  } else {
    body.add_line(refs[0], refs[1], begin, finish);
  }
  return static_cast<std::size_t>(p - at);
}

}  // namespace hlr::lang
