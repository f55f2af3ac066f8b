// Text scanning shared by the text formats: lines, tokens with columns, and strict number parsing that
// reports the offending token (std::from_chars: exact, locale-independent, never reads past the token).
#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>

#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib::mesh_detail {

namespace {

int saturate(std::size_t n) { return static_cast<int>(std::min<std::size_t>(n, INT_MAX)); }

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

// Drops a leading '+' that from_chars would refuse ("+1.5" is common in exported files).
std::string_view without_plus(std::string_view s) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
  return s;
}

// An out-of-range decimal is an underflow (→ ±0) when its exponent is negative or it has no exponent and
// no integer digits; otherwise it overflowed.
bool is_underflow(std::string_view s) {
  const std::size_t e = s.find_first_of("eE");
  if (e != std::string_view::npos) return e + 1 < s.size() && s[e + 1] == '-';
  if (!s.empty() && (s[0] == '-' || s[0] == '+')) s.remove_prefix(1);
  return s.starts_with("0.") || s.starts_with(".");
}

}  // namespace

void fail(const std::string& file, int line, int column, std::string message, std::string hint) {
  throw MeshImportError(MeshProblem{file, line, column, std::move(message), std::move(hint)});
}

std::string quoted(std::string_view token) {
  constexpr std::size_t kMax = 24;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMax; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    }
  }
  if (token.size() > kMax) out += "...";
  return out + "'";
}

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           const auto lower = [](char c) {
             return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
           };
           return lower(x) == lower(y);
         });
}

bool parse_real(std::string_view text, double& out) {
  const std::string_view s = without_plus(text);
  if (s.empty()) return false;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out, std::chars_format::general);
  if (end != s.data() + s.size()) return false;
  if (ec == std::errc::result_out_of_range) {
    if (!is_underflow(s)) {
      out = s[0] == '-' ? -HUGE_VAL : HUGE_VAL;
      return true;
    }
    out = s[0] == '-' ? -0.0 : 0.0;
    return true;
  }
  return ec == std::errc{};
}

bool parse_integer(std::string_view text, std::int64_t& out) {
  const std::string_view s = without_plus(text);
  if (s.empty()) return false;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc{} && end == s.data() + s.size();
}

// ---- LineScanner
// -------------------------------------------------------------------------------------------

LineScanner::LineScanner(std::string_view text) : rest_(text) {
  if (rest_.starts_with("\xEF\xBB\xBF")) rest_.remove_prefix(3);
}

bool LineScanner::next() {
  if (rest_.empty()) return false;
  const std::size_t end = rest_.find_first_of("\r\n");
  if (end == std::string_view::npos) {
    current_ = rest_;
    rest_ = {};
  } else {
    current_ = rest_.substr(0, end);
    const bool crlf = rest_[end] == '\r' && end + 1 < rest_.size() && rest_[end + 1] == '\n';
    rest_.remove_prefix(end + (crlf ? 2 : 1));
  }
  if (line_ < INT_MAX) ++line_;
  tokens_.clear();
  return true;
}

const std::vector<Token>& LineScanner::tokens(char comment) {
  tokens_.clear();
  std::string_view line = current_;
  if (comment != 0) line = line.substr(0, line.find(comment));
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i])) ++i;
    if (i > start) tokens_.push_back({line.substr(start, i - start), saturate(start + 1)});
  }
  return tokens_;
}

// ---- LineContext
// -----------------------------------------------------------------------------------------------

void LineContext::fail(int column, std::string message, std::string hint) const {
  mesh_detail::fail(file_, line_, column, std::move(message), std::move(hint));
}

double LineContext::any_real(const Token& t, const char* what) const {
  double v = 0;
  if (!parse_real(t.text, v))
    fail(t.column, std::string("bad number ") + quoted(t.text) + " for " + what,
         "write decimal numbers such as 12, -0.5 or 1.25e-3");
  return v;
}

double LineContext::real(const Token& t, const char* what) const {
  const double v = any_real(t, what);
  if (!std::isfinite(v)) {
    const char last = t.text.back();  // "1e999" overflowed; "inf", "nan" were written as such
    const bool overflow = std::isinf(v) && ((last >= '0' && last <= '9') || last == '.');
    fail(t.column,
         overflow ? std::string("number ") + quoted(t.text) + " for " + what + " is too large for a double"
                  : std::string(what) + " is not a finite number (" + quoted(t.text) + ")",
         "every coordinate must be a finite number; fix or remove the vertex");
  }
  return v;
}

std::int64_t LineContext::integer(const Token& t, const char* what, std::int64_t lo, std::int64_t hi) const {
  std::int64_t v = 0;
  if (!parse_integer(t.text, v)) {
    double real = 0;
    const std::string_view s = without_plus(t.text);
    const bool digits = !s.empty() && std::all_of(s.begin() + (s[0] == '-' ? 1 : 0), s.end(), [](char c) {
      return c >= '0' && c <= '9';
    }) && s != "-";
    if (digits)
      fail(t.column, std::string(what) + " " + quoted(t.text) + " is too large",
           "the value must be between " + std::to_string(lo) + " and " + std::to_string(hi));
    if (parse_real(t.text, real))
      fail(t.column, std::string("expected a whole number for ") + what + ", found " + quoted(t.text),
           "write it without a decimal point or exponent");
    fail(t.column, std::string("bad number ") + quoted(t.text) + " for " + what,
         "write a whole number such as 3");
  }
  if (v < lo || v > hi)
    fail(t.column, std::string(what) + " " + std::to_string(v) + " is out of range",
         "the value must be between " + std::to_string(lo) + " and " + std::to_string(hi));
  return v;
}

}  // namespace hlr::stdlib::mesh_detail
