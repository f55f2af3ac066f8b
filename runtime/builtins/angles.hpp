// Trigonometry in degrees, exact where the values are simple: sin(180) is 0, sin(30) is 0.5, tan(45) is 1,
// and rotate(z: 90) maps x to y exactly, so right-angle placements keep faces coplanar and coordinates
// whole. The reductions below are exact in floating point (Sterbenz: x − y is exact for y/2 ≤ x ≤ 2y).
#pragma once

#include <cmath>
#include <numbers>

namespace hlr::runtime {

inline double sin_deg(double deg) {
  double r = std::fmod(deg, 360.0);
  if (r < 0) r += 360;
  if (r >= 180) return -sin_deg(r - 180);
  if (r > 90) r = 180 - r;
  if (r == 0) return 0;
  if (r == 30) return 0.5;
  if (r == 90) return 1;
  return std::sin(r * std::numbers::pi / 180);
}

inline double cos_deg(double deg) {
  double r = std::fmod(deg, 360.0);
  if (r < 0) r += 360;
  return r <= 180 ? sin_deg(90 - r) : sin_deg(r - 270);
}

// ±90° (mod 180) gives an infinity, which callers report as a non-finite result.
inline double tan_deg(double deg) {
  const double c = cos_deg(deg);
  return c == 0 ? HUGE_VAL : sin_deg(deg) / c;
}

inline double rad_to_deg(double rad) { return rad * 180 / std::numbers::pi; }

}  // namespace hlr::runtime
