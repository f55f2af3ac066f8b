// FastCursor: the common case of mesh text read in one pass, without tokens or messages (mesh_detail.hpp
// says how it declines to the careful reader).
#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstring>

#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib::mesh_detail {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

}  // namespace

FastCursor::FastCursor(std::string_view text, char comment)
    : p_(text.data()), end_(text.data() + text.size()), line_start_(text.data()), comment_(comment) {
  if (text.starts_with("\xEF\xBB\xBF")) p_ = line_start_ = p_ + 3;  // as LineScanner: columns after it
}

FastCursor::FastCursor(std::string_view part, int first_line, char comment)
    : p_(part.data()),
      end_(part.data() + part.size()),
      line_start_(part.data()),
      line_(first_line),
      comment_(comment) {}

int FastCursor::column() const {
  return static_cast<int>(std::min<std::ptrdiff_t>(p_ - line_start_, INT_MAX - 1)) + 1;
}

bool FastCursor::boundary(const char* q) const {
  return q == end_ || is_blank(*q) || *q == '\n' || *q == '\r' || (comment_ != 0 && *q == comment_);
}

void FastCursor::skip_blanks() {
  while (p_ != end_ && is_blank(*p_)) ++p_;
}

void FastCursor::skip_line() {
  while (p_ != end_ && *p_ != '\n' && *p_ != '\r') ++p_;
  if (p_ == end_) return;
  p_ += *p_ == '\r' && p_ + 1 != end_ && p_[1] == '\n' ? 2 : 1;
  if (line_ < INT_MAX) ++line_;
  line_start_ = p_;
}

bool FastCursor::next_record() {
  for (;;) {
    skip_blanks();
    if (p_ == end_) return false;
    if (*p_ != '\n' && *p_ != '\r' && (comment_ == 0 || *p_ != comment_)) break;
    skip_line();
  }
  return true;
}

bool FastCursor::at_line_end() const {
  const char* q = p_;
  while (q != end_ && is_blank(*q)) ++q;
  return q == end_ || *q == '\n' || *q == '\r' || (comment_ != 0 && *q == comment_);
}

bool FastCursor::end_of_line() {
  if (!at_line_end()) return false;
  skip_line();
  return true;
}

bool FastCursor::real(double& out) {
  const auto [ptr, ec] = std::from_chars(p_, end_, out, std::chars_format::general);
  if (ec != std::errc{} || ptr == p_ || !boundary(ptr) || !std::isfinite(out)) return false;
  p_ = ptr;
  skip_blanks();
  return true;
}

bool FastCursor::index(std::uint64_t& out) {
  const char* q = p_;
  std::uint64_t v = 0;
  while (q != end_ && *q >= '0' && *q <= '9' && q - p_ < 18)
    v = 10 * v + static_cast<std::uint64_t>(*q++ - '0');
  if (q == p_ || !boundary(q)) return false;
  out = v;
  p_ = q;
  skip_blanks();
  return true;
}

bool FastCursor::word(std::string_view& out) {
  const char* q = p_;
  while (!boundary(q)) ++q;
  if (q == p_) return false;
  out = std::string_view(p_, static_cast<std::size_t>(q - p_));
  p_ = q;
  skip_blanks();
  return true;
}

std::vector<std::string_view> split_at_line_ends(std::string_view text, std::size_t bytes) {
  std::vector<std::string_view> parts;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.size();
    if (text.size() - begin > bytes) {
      const std::size_t newline = text.find('\n', begin + bytes - 1);
      if (newline != std::string_view::npos) end = newline + 1;
    }
    parts.push_back(text.substr(begin, end - begin));
    begin = end;
  }
  if (parts.empty()) parts.push_back(text);
  return parts;
}

bool count_lines_and_records(std::string_view part, char comment, PartCounts& out) {
  out = {};
  const char* p = part.data();
  const char* const end = p + part.size();
  for (const char* cr = p;
       (cr = static_cast<const char*>(std::memchr(cr, '\r', static_cast<std::size_t>(end - cr)))); ++cr)
    if (cr + 1 == end || cr[1] != '\n') return false;
  while (p != end) {
    while (p != end && is_blank(*p)) ++p;
    if (p != end && *p != '\n' && *p != '\r' && (comment == 0 || *p != comment)) ++out.records;
    const auto* newline = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    if (!newline) break;
    ++out.lines;
    p = newline + 1;
  }
  return true;
}

}  // namespace hlr::stdlib::mesh_detail
