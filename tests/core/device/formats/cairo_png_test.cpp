// The PNG device's choice of storage (grey when every pen is grey, colour otherwise) and that the grey
// path draws what the colour path draws: both are read back with libpng's own reader.
#include <gtest/gtest.h>
#include <png.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "core/device/formats/cairo_device.hpp"
#include "tests/support/png_decode.hpp"

namespace hlr {
namespace {

using Decoded = test::DecodedPng;
Decoded decode(const std::string& bytes) { return test::decode_png(bytes); }

PlotStroke line(Point2 a, Point2 b, int pen, StrokeLayer layer = StrokeLayer::Visible) {
  PlotStroke s;
  s.points = {a, b};
  s.pen = pen;
  s.layer = layer;
  return s;
}

// 100 × 50 mm: pens 1 and 3 crossing (3 over 1), a dashed pen-1 stroke, a diagonal, one clipped at the
// page's edge, the border and the caption.
PlotPage grey_page() {
  PlotPage page;
  page.width_mm = 100;
  page.height_mm = 50;
  page.margin_mm = 5;
  page.strokes = {line({10, 10}, {90, 30}, 1), line({10, 30}, {90, 10}, 3),
                  line({10, 20}, {90, 20}, 1, StrokeLayer::Hidden), line({12, 38}, {1e9, 36}, 1)};
  page.border = Rect2{5, 5, 95, 40};
  page.caption = "grey caption";
  return page;
}

CairoOptions png_options(double dpi = 150) {
  CairoOptions o;
  o.format = CairoFormat::Png;
  o.dpi = dpi;
  o.pens.set(1, {0.5, 0.5, 0.5, 0.6});  // mid grey, 0.6 mm
  o.pens.set(3, {0.2, 0.2, 0.2, 1.0});  // dark grey, 1 mm
  return o;
}

TEST(CairoPng, StorageFollowsThePens) {
  PlotPage page = grey_page();
  CairoOptions o = png_options();
  EXPECT_EQ(decode(cairo_page_bytes(page, o)).colour_type, PNG_COLOR_TYPE_GRAY);
  o.white_background = false;
  EXPECT_EQ(decode(cairo_page_bytes(page, o)).colour_type, PNG_COLOR_TYPE_RGB_ALPHA) << "grey pens, no paper";
  o = png_options();
  o.pens.set(1, {0, 0, 0, 0.25});
  o.pens.set(3, {0, 0, 0, 0.25});
  o.white_background = false;
  EXPECT_EQ(decode(cairo_page_bytes(page, o)).colour_type, PNG_COLOR_TYPE_GRAY_ALPHA)
      << "black pens, no paper";
  page.strokes.push_back(line({50, 45}, {51, 45}, 2));  // pen 2 is red
  EXPECT_EQ(decode(cairo_page_bytes(page, o)).colour_type, PNG_COLOR_TYPE_RGB_ALPHA);
  o.white_background = true;
  EXPECT_EQ(decode(cairo_page_bytes(page, o)).colour_type, PNG_COLOR_TYPE_RGB);
}

// Grey pens drawn as ink on one byte a pixel give the picture cairo draws in colour: the same page with
// a red dot added in a corner (which makes it colour) differs nowhere else by more than rounding.
TEST(CairoPng, GreyInkMatchesTheColourPicture) {
  for (const double dpi : {60.0, 150.0}) {
    const PlotPage grey = grey_page();
    PlotPage coloured = grey;
    coloured.strokes.push_back(line({98, 1}, {98.5, 1}, 2));
    const Decoded g = decode(cairo_page_bytes(grey, png_options(dpi)));
    const Decoded c = decode(cairo_page_bytes(coloured, png_options(dpi)));
    ASSERT_EQ(g.colour_type, PNG_COLOR_TYPE_GRAY);
    ASSERT_EQ(c.colour_type, PNG_COLOR_TYPE_RGB);
    ASSERT_EQ(g.width, c.width);
    ASSERT_EQ(g.height, c.height);
    const long corner_x = static_cast<long>(96 * dpi / 25.4), corner_y = static_cast<long>(3 * dpi / 25.4);
    int worst = 0, inked = 0;
    for (long y = 0; y < g.height; ++y)
      for (long x = 0; x < g.width; ++x) {
        if (x >= corner_x && y <= corner_y) continue;
        inked += g.at(x, y)[0] < 250;
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(g.at(x, y)[k] - c.at(x, y)[k]));
      }
    EXPECT_LE(worst, 2) << dpi << " dpi";
    EXPECT_GT(inked, 1000) << dpi << " dpi: the page is drawn";
  }
}

// Antialiasing stays: across a diagonal, pixels take many levels between paper and ink, for pens a few
// pixels wide (4 × 4 samples) and for hairlines (256 levels) alike.
TEST(CairoPng, DiagonalsAreAntialiased) {
  for (const double width_mm : {0.25, 0.05}) {
    PlotPage page;
    page.width_mm = 100;
    page.height_mm = 50;
    page.margin_mm = 5;
    page.strokes = {line({10, 10}, {90, 37}, 1)};
    CairoOptions o;
    o.format = CairoFormat::Png;
    o.pens.set_default_width(width_mm);
    o.decorations = false;
    const Decoded d = decode(cairo_page_bytes(page, o));
    std::set<int> levels;
    for (long y = 0; y < d.height; ++y)
      for (long x = 0; x < d.width; ++x)
        if (d.at(x, y)[0] > 0 && d.at(x, y)[0] < 255) levels.insert(d.at(x, y)[0]);
    EXPECT_GE(levels.size(), 10u) << width_mm << " mm";
  }
}

}  // namespace
}  // namespace hlr
