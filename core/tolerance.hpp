// The one tolerance policy of hlrscript's geometry. Every comparison that is not exact goes through a
// value defined here; nothing else in core defines an epsilon.
//
// Why these values: coordinates are doubles (unit round-off u = 2^-53 ≈ 1.1e-16). The engine's longest
// chains (projection, plane evaluation, segment intersection) take about 20 operations, so by pbrt's
// gamma(n) = n·u/(1 − n·u) bound their relative error is below 1e-14 of the magnitudes involved. We
// allow a margin of 10^5 over that, giving a relative tolerance of 1e-9, which is still far below any
// drawing resolution (1e-9 of a 1 m sheet is a nanometre). Tolerances are scaled to the scene: a
// `Tolerance` is built from the extent of the data it compares, never used as an absolute constant.
#pragma once

#include <algorithm>
#include <cmath>

namespace hlr {

struct Tolerance {
  // Relative coincidence tolerance (see above).
  static constexpr double kRelative = 1e-9;
  // A face is planar when every vertex lies within kPlanarity·(face diameter) of its best-fit plane;
  // looser than kRelative because user data typed with 6 significant digits (the theses' cards) must pass.
  static constexpr double kPlanarity = 1e-6;
  // Two faces sharing an edge are coplanar (the edge is not drawn) when their unit normals differ by
  // less than this angle, in radians (≈ 0.0006°): catches data rounded to 6 digits, nothing visible.
  static constexpr double kCoplanarAngle = 1e-5;

  double length = 0;  // absolute length tolerance in the units of the data compared

  // Tolerance for data whose coordinates have magnitude up to `extent`.
  static Tolerance for_extent(double extent) {
    return Tolerance{kRelative * std::max(std::abs(extent), 1e-300)};
  }
};

}  // namespace hlr
