#include "core/format_number.hpp"

#include <cmath>
#include <cstdio>

namespace hlr {
namespace {

// Below this a whole double is exact in decimal and short enough to print in full.
constexpr double kWholeDigits = 1e15;

}  // namespace

std::string format_for_message(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (value == 0) return "0";  // also for -0
  char buf[32];
  const bool whole = std::floor(value) == value && std::fabs(value) < kWholeDigits;
  std::snprintf(buf, sizeof buf, whole ? "%.0f" : "%g", value);
  return buf;
}

std::string format_mm_for_message(double mm) {
  // Far out (or not finite), a tenth of a millimetre is below the double's own step: print as it is.
  if (!(std::fabs(mm) < kWholeDigits)) return format_for_message(mm);
  return format_for_message(std::round(mm * 10) / 10);
}

}  // namespace hlr
