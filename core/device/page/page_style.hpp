// How a page looks on the drawing devices (PDF, SVG, PNG), in one place so that every format draws the
// same picture: hidden strokes dashed, a thin grey border round the camera frame, the caption in the
// bottom margin, strokes clipped a little outside the page.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/device/page/pen_style.hpp"
#include "core/device/page/plot_page.hpp"
#include "core/geometry/rect2.hpp"

namespace hlr {

inline constexpr double kMmPerInch = 25.4;
inline constexpr double kPointsPerMm = 72.0 / kMmPerInch;
// Hidden strokes: 2 mm dashes, 1.2 mm gaps as seen. Round caps lengthen each dash by the pen's width,
// so the drawn dash is shortened and the gap widened by it.
inline constexpr double kDashMm = 2, kGapMm = 1.2;
// Drawn by occlusion level (PlotStroke::level), level 1 as plain hidden strokes and each level deeper
// kLevelStepMm less dash (never under kMinDashMm) and kLevelStepMm more gap: deeper is sparser, and no two
// levels share a pattern (2/1.2, 1.6/1.6, 1.2/2, 0.8/2.4, 0.4/2.8, 0.4/3.2, … 0.4/7.2 mm at level 16).
inline constexpr double kLevelStepMm = 0.4, kMinDashMm = 0.4;
inline double level_dash_mm(int level) {
  return std::max(kMinDashMm, kDashMm - kLevelStepMm * (std::max(level, 1) - 1));
}
inline double level_gap_mm(int level) { return kGapMm + kLevelStepMm * (std::max(level, 1) - 1); }
inline double dash_on_mm(double width_mm, int level = 1) {
  return std::max(0.0, level_dash_mm(level) - width_mm);
}
inline double dash_off_mm(double width_mm, int level = 1) { return level_gap_mm(level) + width_mm; }
inline constexpr double kBorderGrey = 0.5;  // the camera frame's border, at half the default pen width
inline constexpr double kCaptionPt = 10;    // sans serif, at (margin, height − 0.6·margin)
// Rasters draw pens at least this many pixels wide with 4 × 4 samples a pixel, thinner ones with 256
// coverage levels (core/device/formats/cairo_device.cpp).
inline constexpr double kFastAntialiasMinPixels = 1;
// Strokes are clipped to the page grown by this much (plus the widest pen), so that caps at the edge
// are drawn whole and no device sees coordinates beyond its range.
inline constexpr double kClipPadMm = 10;

inline Rect2 stroke_clip_box(const PlotPage& page, const PenTable& pens) {
  double widest = 0;
  for (const PlotStroke& s : page.strokes) widest = std::max(widest, pens.style(s.pen).width_mm);
  const double pad = kClipPadMm + widest;
  return {-pad, -pad, page.width_mm + pad, page.height_mm + pad};
}

// Consecutive strokes of one pen, layer and level are drawn as one path (the same picture, smaller files;
// dashes restart on every subpath): draw(style, layer, level, first, last) for each run [first, last).
template <typename Draw>
void for_each_pen_run(const PlotPage& page, const PenTable& pens, Draw&& draw) {
  const std::vector<PlotStroke>& strokes = page.strokes;
  for (std::size_t i = 0; i < strokes.size();) {
    std::size_t end = i + 1;
    while (end < strokes.size() && strokes[end].pen == strokes[i].pen &&
           strokes[end].layer == strokes[i].layer && strokes[end].level == strokes[i].level)
      ++end;
    draw(pens.style(strokes[i].pen), strokes[i].layer, strokes[i].level, i, end);
    i = end;
  }
}

}  // namespace hlr
