// Doubles rounded outward to floats: bounds half the size that are never tighter than the doubles they
// stand for, so a quick reject on them rejects only what the doubles would (what they let through is
// then tested in doubles).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace hlr {

// The largest float ≤ x, for finite x (beyond the floats' range: their max, or −∞).
inline float float_below(double x) {
  const auto f = static_cast<float>(x);
  if (static_cast<double>(f) <= x) return f;
  if (std::isinf(f)) return std::numeric_limits<float>::max();
  if (f == 0) return -std::numeric_limits<float>::denorm_min();
  const auto bits = std::bit_cast<std::uint32_t>(f);  // one step towards −∞
  return std::bit_cast<float>(f > 0 ? bits - 1 : bits + 1);
}

// The smallest float ≥ x, for finite x.
inline float float_above(double x) { return -float_below(-x); }

}  // namespace hlr
