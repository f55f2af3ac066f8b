// What every device draws: one page of strokes in page millimetres, already in plotting order.
//
// The pipeline is visible set → page layout (core/device/page/page_layout.hpp) → pen plan (core/plan/) →
// device. Devices never reorder or rejoin strokes, so PDF, SVG, PNG, HPGL and JSON show the same strokes
// in the same order, and the plan's statistics describe what each of them draws.
//
// Page coordinates: millimetres from the page's top-left corner, x right, y down (as PDF and SVG).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/geometry/rect2.hpp"
#include "core/geometry/vector.hpp"
#include "core/plan/plot_stroke.hpp"

namespace hlr {

struct PlotPage {
  double width_mm = 297;  // A4 landscape
  double height_mm = 210;
  double margin_mm = 12;
  std::vector<PlotStroke> strokes;  // in plotting order
  // The camera frame on the page (mm), drawn as a thin border by the cairo devices; HPGL leaves it out.
  std::optional<Rect2> border;
  std::string caption;  // cairo devices print it in the bottom margin
};

}  // namespace hlr
