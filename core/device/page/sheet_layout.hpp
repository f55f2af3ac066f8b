// A sheet of views: several cameras' drawings on one page, as a technical drawing has its front, top and
// side views and an isometric one. Each view puts its picture origin (the camera's target) at a page point
// in millimetres and has its own scale; views without one share the sheet's scale — the paper's `scale:`,
// else the largest ISO 5455 scale (1, 2 or 5 × 10^k mm per unit) at which every such view, with its label
// under it and its dimensions' room about it, stays inside the page's margins. A scale is millimetres per world unit: exact everywhere in
// an orthographic view, at the target's depth in a perspective one (world_per_picture_unit). Scales are
// written as ratios reading one unit as a millimetre ("1:2", "5:1").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/device/page/page_layout.hpp"
#include "core/geometry/rect2.hpp"
#include "core/geometry/vector.hpp"

namespace hlr {

// How far a view's dimensions reach past its drawing on the page, mm on each side (page y down: `top` is
// above the drawing). The fits keep that room too, and the label goes below the bottom one.
struct ViewMargins {
  double left = 0, top = 0, right = 0, bottom = 0;
};

// What the scale fit needs of one view.
struct SheetViewFit {
  Point2 at_mm;                       // where the picture origin lands (page mm, top-left, y down)
  std::optional<double> mm_per_unit;  // its own scale; views with one are not fitted
  Rect2 extent;  // its extent in world units about the target (the camera's frame, else what it draws)
  double label_band_mm = 0;  // room its label needs below the drawing
  ViewMargins dimensions;    // room its dimensions take beyond the drawing
};

// Height of a view's label, and the gap between the drawing and it (the label's band: gap, capitals and
// descenders).
inline constexpr double kViewLabelCapMm = 3.5;
inline constexpr double kViewLabelGapMm = 5;
inline constexpr double kViewLabelBandMm = kViewLabelGapMm + kViewLabelCapMm * (1 + 7.0 / 21.0);

// World units per picture unit of `camera`: 1/focal orthographic; perspective, at the target's depth
// (Camera::target_depth, else `fallback_depth` when positive, else 1).
double world_per_picture_unit(const Camera& camera, double fallback_depth);

// The largest 1, 2 or 5 × 10^k not above `mm_per_unit` (which must be finite and positive).
double iso_scale_at_most(double mm_per_unit);

// "1:2", "2:1", "1:1", "1:2.5" (up to four significant digits).
std::string scale_ratio_text(double mm_per_unit);

// Gap kept between views, and between a view and the title block, when the scale is fitted.
inline constexpr double kViewGapMm = 5;

// The scale of the views without their own: `spec.mm_per_unit` when set, else the largest ISO scale at
// which each of them, with its label, fits inside the margins around its point, kViewGapMm clear of every
// other view (apart along x or along y) and of `keep_out` (the title block); 1 when none has anything to
// fit. A view whose point lies on or outside the margins, and a bound no positive scale meets (two views
// at one point), do not constrain it (the caller warns about what overlaps).
double fitted_sheet_scale(const std::vector<SheetViewFit>& views, const PageSpec& spec,
                          const Rect2& keep_out = Rect2::none());

// Views in a grid (`views of PART`: the standard views in first- or third-angle projection): a column and
// a row each, columns as wide as their views, rows as tall as their views and labels, `gap_mm` apart, the
// grid centred in an area of the sheet. Each column's views share their targets' x on the page and each
// row's their y, so a front view and the top view above it line up as projections do.
struct GridViewFit {
  int column = 0, row = 0;
  Rect2 extent;  // world units about the target (SheetViewFit::extent)
  double label_band_mm = 0;
  ViewMargins dimensions;
};
// Where each view's target lands at `mm_per_unit`.
std::vector<Point2> grid_view_points(const std::vector<GridViewFit>& views, double mm_per_unit,
                                     const Rect2& area, double gap_mm);
// The largest ISO scale at which the grid fits inside `area`; 1 when nothing has an extent or no positive
// scale fits (the caller's warnings then say what runs off).
double fitted_grid_scale(const std::vector<GridViewFit>& views, const Rect2& area, double gap_mm);

// The layout of a view: picture (0, 0) at `at_mm`, `mm_per_picture_unit` millimetres per picture unit.
PageLayout view_layout(const Paper& paper, Point2 at_mm, double mm_per_picture_unit);

// The sheet's frame (the margin's rectangle) and its title block in the frame's bottom-right corner,
// page mm. The title block is empty when the page has too little room for one.
struct SheetFrame {
  Rect2 frame;
  Rect2 title_block;
};
SheetFrame sheet_frame(const PageSpec& spec);

}  // namespace hlr
