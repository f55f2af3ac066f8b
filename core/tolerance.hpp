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
  // Two triangles whose planes meet at a smaller angle (sine of it) have their crossing constructed
  // exactly (core/geometry/exact_crossing.hpp): in doubles the line's position errs by ~u / angle, which
  // here would pass 1e-12 of their size. Faces of more corners are planar only to kPlanarity, and below
  // kCoplanarAngle they keep to that rule: no line.
  static constexpr double kExactCrossingAngle = 1e-4;
  // Two lines of the picture at a smaller angle (sine) cross where floating point puts them only to within
  // ~u / angle of their length; the occlusion test then adds a triangle's exact crossing as well.
  static constexpr double kNearlyParallel = 1e-6;
  // A positive floor for a scale or a divisor: keeps it nonzero, and is below every real length.
  static constexpr double kFloor = 1e-300;

  double length = 0;  // absolute length tolerance in the units of the data compared

  // Picture-space tolerance for comparisons among projected points whose largest |coordinate| is
  // `max_abs`: projection keeps relative error, so the tolerance is relative to those coordinates — local,
  // so that geometry projected far off-axis (near the near plane) does not coarsen the rest of the
  // picture — but never below the view-space tolerance `length` seen at the nearest `depth` (perspective;
  // pass depth = 1 for orthographic, where picture = focal · view).
  static double picture(double max_abs, double focal, double length, double depth) {
    return std::max(kRelative * max_abs, std::abs(focal) * length / std::max(depth, kFloor));
  }

  // Rounding of coordinates themselves: the engine works in view space, where every coordinate comes from
  // a world coordinate through ~10 operations; bounding 64 of them (pbrt's gamma(64) ≈ 7.1e-15) covers the
  // transform with margin. Far from the world origin this, not kRelative, is the honest floor.
  static constexpr double kRounding = 64 * 0x1p-53;

  // View-space tolerance: relative to the view-space extent of the scene, plus the rounding carried from
  // world coordinates of magnitude up to `world_extent` (so a scene translated far from the origin keeps
  // its decisions).
  static Tolerance for_view(double view_extent, double world_extent) {
    return Tolerance{kRelative * std::abs(view_extent) + kRounding * std::abs(world_extent) + kFloor};
  }

  // Tolerance for data whose coordinates have magnitude up to `extent`.
  static Tolerance for_extent(double extent) {
    return Tolerance{kRelative * std::max(std::abs(extent), kFloor)};
  }

  // ---- Paths (core/animation): a tangent is a difference quotient over this fraction of one stretch
  // between two points — small against the stretch, large against the 1e-16 rounding of u.
  static constexpr double kPathTangentStep = 1e-4;

  // ---- Cameras: near planes (perspective). Only keep 1/depth defined; none cuts a visible object.
  // Camera's default near depth, in view depth units, when its constructor sets none.
  static constexpr double kDefaultNearDepth = 1e-3;
  // lookat()'s default near depth per unit of |target − eye|: far enough to keep 1/depth tame.
  static constexpr double kLookatNearFraction = 1e-4;
  // orbit()'s near depth per unit of ρ: Albers never clips at the eye, so as close to it as is safe.
  static constexpr double kOrbitNearFraction = 1e-6;

  // ---- Hatching (core/solid/hatching.cpp): a cross product of unit vectors shorter than this (an angle in
  // radians) leaves no direction — a face level to it has x for its horizontal, a face parallel to the
  // cutting planes no lines.
  static constexpr double kHatchDirection = 1e-9;

  // ---- Solid generators (stdlib), relative to the generator's coordinates or sizes.
  // Smallest feature (profile size, grid step, ring spacing) per unit of the largest coordinate: 100 ×
  // kRelative, so the feature's vertices stay apart by far more than the builder's coincidence tolerance.
  static constexpr double kGeneratorFeature = 1e-7;
  // sweep(): a unit start tangent whose part across +z is shorter than this is vertical (up is then +y).
  static constexpr double kSweepVertical = 1e-6;
  // sweep(): unit tangents whose dot product is within this of −1 reverse the path (no mitre exists).
  static constexpr double kSweepReversal = 1e-12;
  // sweep(): a closed path's frame twist round the loop, in radians, below which the ring closes flat.
  static constexpr double kSweepTwist = 1e-9;
  // sweep(): a mitred lateral line must run forward by more than this fraction of the profile's size.
  static constexpr double kSweepMitre = 1e-6;
  // heightfield(): a cell stays one quad when its warp is below this fraction of the heights' scale:
  // rounding of a four-term sum of heights (≈ 4·2^-53) with margin.
  static constexpr double kHeightfieldWarp = 1e-12;
  // Triangulation: a ring's turning angle within this of 2π (radians) turns once; n atan2 calls each
  // err by ~1e-16.
  static constexpr double kTurning = 1e-6;
  // Desens' carrier hull (faces 13–16) deviates from planarity by up to 2.7e-3 of its size (1969 data).
  static constexpr double kDesensCarrierPlanarity = 3e-3;

  // ---- Pen planning, in device grid units (coordinates up to 2^29, so sums round at ~1e-7).
  // A 2-opt or Or-opt move must shorten the tour by more than this, or rounding could make moves cycle.
  static constexpr double kPlanGain = 1e-7;
  // A swap of matched odd vertices must gain more than this fraction of (distance + 1): the same
  // anti-cycling guard, relative to the distances compared.
  static constexpr double kPlanMatchingGain = 1e-9;
  // Smallest width and height of the neighbour grid's box: a set of points on a line still gets cells.
  static constexpr double kPlanGridExtent = 1e-9;
  // Slack on the reach of a merge tolerance across a piece: a vertex exactly at the tolerance is on it.
  static constexpr double kPlanReachSlack = 1e-9;
  // A hidden piece lying on a visible one (or a deeper level's on a shallower one) within this many page
  // mm is not drawn there (core/plan/hidden_precedence.hpp): far below any pen's step (0.025 mm), far
  // above the rounding of the layout (~1e-12 mm), so lines that coincide in an orthographic view do.
  static constexpr double kCoincidentLineMm = 1e-3;

  // ---- Sheets of views (core/device/page/sheet_layout.hpp, dimension_strokes.hpp).
  // A scale within this relative slack of an ISO scale is that scale (1 − 1e-12 of 2 is still 2:1).
  static constexpr double kIsoScaleRelative = 1e-12;
  // A view's drawing this many mm past the margins still lies inside them (the layout's rounding).
  static constexpr double kSheetMarginSlackMm = 1e-6;
  // A dimension whose points fall closer than this on the page is not drawn (nothing to read between them).
  static constexpr double kDimensionMinSpanMm = 0.1;
  // A dimension line's page direction with an x component within this of 0 is upright (read bottom to top).
  static constexpr double kDimensionUprightSlack = 1e-12;
  // An angle dimension's arc is drawn as chords that leave it by at most this many mm: half a pen step.
  static constexpr double kDimensionArcChordMm = 0.01;

  // ---- Devices.
  // HPGL: a sheet edge within this many plotter units of a whole unit is that unit (mm / unit is rarely
  // exact in binary, and the pen must never be sent one unit past the sheet nor lose one).
  static constexpr double kPlotterUnitSnap = 1e-6;
  // HPGL: a page matches a profile's paper when each side is within this many mm of the sheet's.
  static constexpr double kPaperMatchMm = 0.5;
  // G-code: a page this many mm larger than the work area still fits (a page exactly the area's size).
  static constexpr double kWorkAreaSlackMm = 1e-6;
  // G-code: a point printed (3 decimals) on the work area's edge is on it, up to half the last digit.
  static constexpr double kPrintedReachMm = 0.0005;
  // Plotter SVG: points this far off the page, relative to its width + height, are on its edge (rounding
  // in the layout); they are cut at the exact edge.
  static constexpr double kPageEdgeRelative = 1e-6;
};

}  // namespace hlr
