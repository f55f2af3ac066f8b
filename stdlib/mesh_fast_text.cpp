// FastCursor: the common case of mesh text read in one pass, without tokens or messages (mesh_detail.hpp
// says how it declines to the careful reader).
#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>

#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib::mesh_detail {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

}  // namespace

FastCursor::FastCursor(std::string_view text, char comment)
    : p_(text.data()), end_(text.data() + text.size()), line_start_(text.data()), comment_(comment) {
  if (text.starts_with("\xEF\xBB\xBF")) p_ = line_start_ = p_ + 3;  // as LineScanner: columns after it
}

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

}  // namespace hlr::stdlib::mesh_detail
