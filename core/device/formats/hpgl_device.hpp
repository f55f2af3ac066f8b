// The HPGL device: one PlotPage as HP-GL for a plotter profile (core/device/plotters/hpgl_profile.hpp).
//
// Placement. The page is the sheet: a page matches one of the profile's paper ranges (by name when
// HpglOptions::paper is given, else by size, either orientation, within 0.5 mm), and every page
// millimetre lands at its true place on that sheet. A page whose orientation differs from the sheet as
// loaded (a portrait A4 page on a plotter that takes A4 landscape) is turned 90° counter-clockwise: the
// page's top edge lies along the sheet's left edge (the plotter's x_min side), so turning the plotted
// sheet 90° clockwise shows the page upright. rotate_180 turns it a further half turn; y_axis_up flips y.
// The pen's reach is rarely centred on the sheet (the 7475A's A4 area stops 13.9 mm short of the top
// edge): hpgl_min_margin_mm() gives the page margin that keeps a layout within it.
//
// Coordinates. Each point is snapped to whole plotter units first; relative moves are differences of
// snapped points, so the absolute position after any number of moves is exactly the snapped point (no
// drift). Points that snap onto the previous one are dropped; a stroke that collapses to a single point
// is drawn as a dot (`PD;` with no coordinates, at the point), as the cairo devices' round caps show it.
// Every number stays within −32768…32767: relative moves longer than 32000 units are split into collinear
// steps.
//
// Reach. A stroke point outside the area the pen reaches on that sheet (the range's limits, and never off
// the sheet) is an error naming the point and the area, unless `clip`, which cuts strokes at the area's
// edge (Liang–Barsky per segment) and splits them where they leave it.
//
// Output: `IN;`, `VSv;` when a velocity is set, then per stroke: `PU;SPn;` when the pen changes, `PUx,y;`
// to its start (absolute the first time, followed by `PR;` in relative mode), `PD…;` through its points
// with at most max_pairs_per_pd pairs per command; finally `PU;`, `PA;` (relative mode) and `SP0;`, which
// puts the pen away and parks the carriage. A newline follows every command when `newline` is set, and
// ends the file in any case.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/device/page/plot_page.hpp"
#include "core/device/plotters/hpgl_profile.hpp"

namespace hlr {

struct HpglOptions {
  std::string paper;  // the profile's range by name ("A4"); empty: the range matching the page's size
  bool clip = false;  // cut strokes at the reachable area instead of refusing points outside it
  // Overrides of the profile's settings.
  std::optional<bool> relative;
  std::optional<int> max_pairs_per_pd;
  std::optional<bool> newline;
  std::optional<double> velocity_cm_s;  // 0.01…1000; 0: no VS even when the profile has a velocity
};

// Throws DeviceError (checked before anything is written): a profile check_hpgl_profile() refuses, a page
// that is not finite and positive, a page that matches no range (the message lists the sizes the plotter
// takes), a pen outside 1…pen_count, a point that is not finite, a point out of reach without `clip`.
std::string to_hpgl(const PlotPage& page, const HpglProfile& profile, const HpglOptions& options = {});

// to_hpgl() written atomically (core/device/page/atomic_file.hpp).
void write_hpgl(const std::filesystem::path& target, const PlotPage& page, const HpglProfile& profile,
                const HpglOptions& options = {});

// The smallest page margin (mm, the same on all four sides) that keeps everything inside it within the
// pen's reach, for a page of this size on this profile (range chosen as to_hpgl() does; `paper` as
// HpglOptions::paper). 0 for the generic profile. Throws DeviceError as to_hpgl() does for the range.
double hpgl_min_margin_mm(const HpglProfile& profile, double page_width_mm, double page_height_mm,
                          std::string_view paper = {});

// Where the plotter's origin (0, 0) — the pen's position after `IN;` — lies on the page, in page mm: the
// home the pen plan starts from and returns to. Throws as hpgl_min_margin_mm() does.
Point2 hpgl_home_on_page(const HpglProfile& profile, double page_width_mm, double page_height_mm,
                         std::string_view paper = {});

}  // namespace hlr
