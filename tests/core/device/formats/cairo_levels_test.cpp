// Occlusion levels on the drawing devices: each level's hidden strokes dashed in their level's pattern
// (core/device/page/page_style.hpp), measured on the PNG's pixels — the share of each stroke that is
// inked falls level by level as the dashes shorten and the gaps lengthen.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/device/formats/cairo_device.hpp"
#include "core/device/page/page_style.hpp"
#include "tests/support/png_decode.hpp"

namespace hlr {
namespace {

// 100 × 60 mm at 254 dpi: 10 pixels a millimetre. Hidden strokes of pen 1 from x = 10 to 90 mm at
// y = 10, 20, … for levels 1, 2, …; a plain hidden stroke (level 0) at y = 50.
PlotPage levels_page(int deepest) {
  PlotPage page;
  page.width_mm = 100;
  page.height_mm = 60;
  page.margin_mm = 5;
  for (int level = 1; level <= deepest; ++level)
    page.strokes.push_back({{{10, 10.0 * level}, {90, 10.0 * level}}, 1, StrokeLayer::Hidden, level});
  page.strokes.push_back({{{10, 50}, {90, 50}}, 1, StrokeLayer::Hidden, 0});
  return page;
}

// The inked share of the row at y mm between x = 15 and 85 mm.
double ink_share(const test::DecodedPng& png, double y_mm) {
  int ink = 0, total = 0;
  const long y = static_cast<long>(y_mm * 10);
  for (long x = 150; x < 850; ++x, ++total) ink += png.at(x, y)[0] < 128;
  return static_cast<double>(ink) / total;
}

TEST(CairoLevels, EachLevelItsOwnDash) {
  CairoOptions o;
  o.format = CairoFormat::Png;
  o.dpi = 254;
  o.decorations = false;
  const test::DecodedPng png = test::decode_png(cairo_page_bytes(levels_page(4), o));
  ASSERT_EQ(png.width, 1000);
  // Seen with its round caps, each dash is the pattern's dash long (the caps come out of the gap): 2 of
  // every 3.2 mm at level 1, 1.6 at level 2, 1.2 at level 3, 0.8 at level 4.
  for (int level = 1; level <= 4; ++level) {
    const double expected = level_dash_mm(level) / (level_dash_mm(level) + level_gap_mm(level));
    EXPECT_NEAR(ink_share(png, 10.0 * level), expected, 0.06) << "level " << level;
  }
  // Plain hidden lines look like level 1.
  EXPECT_NEAR(ink_share(png, 50), ink_share(png, 10), 0.02);
  for (int level = 2; level <= 4; ++level)
    EXPECT_LT(ink_share(png, 10.0 * level), ink_share(png, 10.0 * (level - 1)) - 0.08) << "level " << level;
}

}  // namespace
}  // namespace hlr
