// The G-code device: one PlotPage as a G-code program for a GRBL pen plotter
// (core/device/plotters/gcode_profile.hpp).
//
// Placement. The page is the paper, taped with its corner at the work area's origin corner: with the
// origin at the bottom-left, page (x, y) is machine (x, page height − y); at the top-left, machine (x, y).
// A page larger than the work area is an error listing the area. A page that would fit only turned 90°
// is refused too, with the hint to turn it (--portrait / --landscape): unlike an HP plotter's sheet
// feed, nothing about a flatbed says which way the paper lies, and a turned drawing surprises.
//
// Reach. The pen draws only on the page: a stroke point off the page (possible with --scale) is an
// error naming the point, unless `clip`, which cuts strokes at the page's edge (Liang–Barsky per
// segment, core/geometry/clip2d.hpp) and splits them where they leave it.
//
// Output: header comments (profile, placement, pen changes, the estimated plotting time from the feeds,
// dwells and lifts), `G21` (mm), `G90` (absolute), pen up; then per stroke in the planned order: when its
// pen differs from the pen in the holder, a comment naming the pen and `M0` (GRBL pauses until
// cycle start) — the program starts with pen 1 in the holder, so a drawing whose first stroke is pen 2
// pauses before it —; `G0 X Y` to its start, pen down (and its dwell), `G1 X Y F<feed>` through its
// points (the feed on the first G1 of each stroke: a Z pen's G1 Z sets another), pen up (and dwell).
// Finally pen up, `G0 X0 Y0` back to the origin and `M2` — except on a servo pen whose up value is above
// its down value: M2 stops the spindle PWM, turning the servo to S0, which would lower that pen. Coordinates
// are written with three decimals (the planning grid, gcode_grid_mm, is coarser), never as -0.000; points
// that print as the previous one are dropped, and a stroke that collapses to one point is a dot (pen down and
// up where it is).
#pragma once

#include <filesystem>
#include <string>

#include "core/device/page/plot_page.hpp"
#include "core/device/plotters/gcode_profile.hpp"

namespace hlr {

struct GcodeOptions {
  bool clip = false;  // cut strokes at the page's edge instead of refusing points off it
};

// The pen plan's grid for G-code: the planning grid of the document devices and JSON (0.025 mm, two
// microsteps of a typical 80 steps/mm belt axis), so the G-code draws exactly the strokes JSON reports.
inline constexpr double kGcodeGridMm = 0.025;

// Throws DeviceError (checked before anything is written): a profile check_gcode_profile() refuses, a page
// that is not finite and positive or larger than the work area, a pen outside 1…pen_count, a point that is
// not finite, a point off the page without `clip`.
std::string to_gcode(const PlotPage& page, const GcodeProfile& profile, const GcodeOptions& options = {});

// Where the machine's origin lies on the page, in page mm: the home the pen plan starts from and returns
// to. Throws as to_gcode() does for the profile and the page size.
Point2 gcode_home_on_page(const GcodeProfile& profile, double page_width_mm, double page_height_mm);

}  // namespace hlr
