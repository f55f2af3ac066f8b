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

  // Picture-space tolerance for comparisons among projected points whose largest |coordinate| is
  // `max_abs`: projection keeps relative error, so the tolerance is relative to those coordinates — local,
  // so that geometry projected far off-axis (near the near plane) does not coarsen the rest of the
  // picture — but never below the view-space tolerance `length` seen at the nearest `depth` (perspective;
  // pass depth = 1 for orthographic, where picture = focal · view).
  static double picture(double max_abs, double focal, double length, double depth) {
    return std::max(kRelative * max_abs, std::abs(focal) * length / std::max(depth, 1e-300));
  }

  // Rounding of coordinates themselves: the engine works in view space, where every coordinate comes from
  // a world coordinate through ~10 operations; bounding 64 of them (pbrt's gamma(64) ≈ 7.1e-15) covers the
  // transform with margin. Far from the world origin this, not kRelative, is the honest floor.
  static constexpr double kRounding = 64 * 0x1p-53;

  // View-space tolerance: relative to the view-space extent of the scene, plus the rounding carried from
  // world coordinates of magnitude up to `world_extent` (so a scene translated far from the origin keeps
  // its decisions).
  static Tolerance for_view(double view_extent, double world_extent) {
    return Tolerance{kRelative * std::abs(view_extent) + kRounding * std::abs(world_extent) + 1e-300};
  }

  // Tolerance for data whose coordinates have magnitude up to `extent`.
  static Tolerance for_extent(double extent) {
    return Tolerance{kRelative * std::max(std::abs(extent), 1e-300)};
  }
};

}  // namespace hlr
