#include "core/device/formats/fixed_decimal.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>

namespace hlr {
namespace {

// The scales a number is rounded at, exact in a double.
constexpr double kScale[] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000};
constexpr int kMostDecimals = 8;
// Scaled values up to this go the short way: their integers fit and their rounding error is tiny.
constexpr double kShortBelow = 1e15;

void append_slowly(std::string& out, double v, int decimals) {
  char buf[400];  // DBL_MAX in fixed point has 309 digits before the point
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  char* end = r.ptr;
  if (decimals > 0) {
    while (end[-1] == '0') --end;
    if (end[-1] == '.') --end;
  }
  if (end - buf == 2 && buf[0] == '-' && buf[1] == '0') {
    out += '0';
    return;
  }
  out.append(buf, end);
}

}  // namespace

// The short way: y = v · 10^decimals is v's value scaled with one rounding (the scale is exact), off by at
// most half an ulp, |y| · 2^-53. Unless y lies within twice that of a half-integer, the exact product
// rounds to y's nearest integer, whatever the error. A page's coordinates almost never lie that close;
// those that do take to_chars. The PDF page of a 10⁶-triangle torus (650 000 numbers) took 46 ms of CPU
// with to_chars alone.
void append_fixed(std::string& out, double v, int decimals) {
  if (decimals < 0 || decimals > kMostDecimals) {
    append_slowly(out, v, decimals);
    return;
  }
  const double y = v * kScale[decimals];
  if (!(std::abs(y) < kShortBelow)) {
    append_slowly(out, v, decimals);
    return;
  }
  const double from_half = std::abs(y - std::floor(y) - 0.5);
  if (from_half <= std::abs(y) * std::numeric_limits<double>::epsilon()) {
    append_slowly(out, v, decimals);
    return;
  }
  const auto rounded = static_cast<std::int64_t>(std::nearbyint(y));
  const std::uint64_t magnitude =
      rounded < 0 ? 0 - static_cast<std::uint64_t>(rounded) : static_cast<std::uint64_t>(rounded);
  const auto unit = static_cast<std::uint64_t>(kScale[decimals]);
  std::uint64_t whole = magnitude / unit, fraction = magnitude % unit;
  char buf[32];  // 15 digits, the point, 8 decimals and the sign
  char* const end = buf + sizeof buf;
  char* p = end;
  int digits = fraction == 0 ? 0 : decimals;  // after the point, trailing zeros dropped
  for (; digits > 0 && fraction % 10 == 0; --digits) fraction /= 10;
  for (int k = 0; k < digits; ++k, fraction /= 10) *--p = static_cast<char>('0' + fraction % 10);
  if (digits > 0) *--p = '.';
  do {
    *--p = static_cast<char>('0' + whole % 10);
    whole /= 10;
  } while (whole != 0);
  if (rounded < 0) *--p = '-';
  out.append(p, end);
}

}  // namespace hlr
