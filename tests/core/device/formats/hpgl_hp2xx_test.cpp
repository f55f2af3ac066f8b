// The HPGL device against an independent interpreter: hp2xx (Debian's 3.4.4) renders our HPGL to PNG, and
// the test rasterises the same PlotPage strokes itself with cairo, placed by the documented convention
// (page y down; a portrait page turned 90° counter-clockwise onto a landscape sheet). hp2xx crops to the
// drawing and knows only the nominal 0.025 mm unit, so both rasters are normalised by their inked bounding
// box with one scale for both axes (an aspect or orientation error still shows), then compared: nearly
// every inked pixel of each must have ink within 2 px in the other (tests/support/raster_compare.hpp).
#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/device/formats/hpgl_device.hpp"
#include "tests/support/raster_compare.hpp"

namespace hlr {
namespace {

namespace fs = std::filesystem;

constexpr double kPxPerMm = 100 / 25.4;  // hp2xx -d 100 at true size

using test::Agreement;
using test::compare_ink;
using test::have_hp2xx;
using test::hp2xx_ink;
using test::Ink;
using test::ink_of;

// The expected picture: the strokes in image pixels through `place` (page mm → px), 1 px black lines.
Ink expected_ink(const PlotPage& page, const std::function<Point2(Point2)>& place, int w, int h) {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
  cairo_t* cr = cairo_create(s);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const PlotStroke& stroke : page.strokes) {
    for (std::size_t i = 0; i < stroke.points.size(); ++i) {
      const Point2 q = place(stroke.points[i]);
      if (i == 0)
        cairo_move_to(cr, q.x, q.y);
      else
        cairo_line_to(cr, q.x, q.y);
    }
    cairo_stroke(cr);
  }
  cairo_destroy(cr);
  Ink ink = ink_of(s);
  cairo_surface_destroy(s);
  return ink;
}

// An asymmetric drawing inside the page's margins: a frame, an F, a circle, a spiral, a star, and a
// zigzag, over three pens.
PlotPage drawing(double w, double h, double margin) {
  PlotPage p;
  p.width_mm = w;
  p.height_mm = h;
  const double x0 = margin, y0 = margin, x1 = w - margin, y1 = h - margin;
  const double cw = x1 - x0, ch = y1 - y0;
  p.strokes.push_back({{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}}, 1});
  const auto at = [&](double u, double v) { return Point2{x0 + u * cw, y0 + v * ch}; };
  p.strokes.push_back({{at(0.1, 0.9), at(0.1, 0.1), at(0.3, 0.1)}, 2});
  p.strokes.push_back({{at(0.1, 0.45), at(0.22, 0.45)}, 2});
  PlotStroke circle{{}, 3};
  const double r = 0.18 * std::min(cw, ch);
  for (int i = 0; i <= 72; ++i)
    circle.points.push_back(
        {x0 + 0.55 * cw + r * std::cos(i * M_PI / 36), y0 + 0.3 * ch + r * std::sin(i * M_PI / 36)});
  p.strokes.push_back(circle);
  PlotStroke spiral{{}, 1};
  for (int i = 0; i <= 400; ++i) {
    const double t = i * 0.05, rr = 0.008 * std::min(cw, ch) * t;  // to 0.16 · min(cw, ch)
    spiral.points.push_back({x0 + 0.8 * cw + rr * std::cos(t), y0 + 0.7 * ch + rr * std::sin(t)});
  }
  p.strokes.push_back(spiral);
  PlotStroke star{{}, 2};
  for (int i = 0; i <= 5; ++i) {
    const double t = i * 4 * M_PI / 5 - M_PI / 2;
    star.points.push_back(
        {x0 + 0.45 * cw + 0.12 * ch * std::cos(t), y0 + 0.72 * ch + 0.12 * ch * std::sin(t)});
  }
  p.strokes.push_back(star);
  PlotStroke zigzag{{}, 3};
  for (int i = 0; i <= 20; ++i) zigzag.points.push_back(at(0.35 + 0.02 * i, i % 2 ? 0.88 : 0.95));
  p.strokes.push_back(zigzag);
  return p;
}

class HpglHp2xx : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(have_hp2xx()) << "hp2xx is not installed: run scripts/setup.sh";
    dir_ = fs::temp_directory_path() / ("hlr-hp2xx-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  // hp2xx's picture of the page against the expectation placed by `place` (page mm → px, y down).
  Agreement check(const PlotPage& page, const HpglProfile& profile,
                  const std::function<Point2(Point2)>& place, int w, int h) {
    const Ink actual = hp2xx_ink(to_hpgl(page, profile), dir_);
    const Ink expected = expected_ink(page, place, w, h);
    return compare_ink(expected, actual);
  }
  fs::path dir_;
};

void expect_agreement(const Agreement& g) {
  EXPECT_TRUE(g.aspect_ok);
  EXPECT_GE(g.expected_found, 0.95) << "actual found " << g.actual_found;
  EXPECT_GE(g.actual_found, 0.95) << "expected found " << g.expected_found;
}

TEST_F(HpglHp2xx, GenericPageMatchesItsRaster) {
  const PlotPage page = drawing(200, 150, 12);
  const auto upright = [](Point2 p) { return Point2{p.x * kPxPerMm, p.y * kPxPerMm}; };
  expect_agreement(check(page, *hpgl_profile_by_name("generic"), upright, 800, 600));
  // The comparison tells a mirror image apart.
  const auto mirrored = [](Point2 p) { return Point2{(200 - p.x) * kPxPerMm, p.y * kPxPerMm}; };
  const Agreement wrong = check(page, *hpgl_profile_by_name("generic"), mirrored, 800, 600);
  EXPECT_LT(std::min(wrong.expected_found, wrong.actual_found), 0.8);  // about 0.43 when written
}

TEST_F(HpglHp2xx, Hp7475aLandscapeA4) {
  const PlotPage page = drawing(297, 210, 15);
  const auto upright = [](Point2 p) { return Point2{p.x * kPxPerMm, p.y * kPxPerMm}; };
  expect_agreement(check(page, *hpgl_profile_by_name("hp7475a"), upright, 1200, 850));
}

// A portrait page on the 7475A's landscape A4 sheet: turned 90° counter-clockwise, its top along the
// sheet's left edge. The clockwise turn (same aspect) must not match.
TEST_F(HpglHp2xx, Hp7475aPortraitA4IsTurnedCounterClockwise) {
  const PlotPage page = drawing(210, 297, 15);
  const auto ccw = [](Point2 p) { return Point2{p.y * kPxPerMm, (210 - p.x) * kPxPerMm}; };
  expect_agreement(check(page, *hpgl_profile_by_name("hp7475a"), ccw, 1200, 850));
  const auto cw = [](Point2 p) { return Point2{(297 - p.y) * kPxPerMm, p.x * kPxPerMm}; };
  const Agreement wrong = check(page, *hpgl_profile_by_name("hp7475a"), cw, 1200, 850);
  EXPECT_LT(std::min(wrong.expected_found, wrong.actual_found), 0.8);  // about 0.43 when written
}

// Clipped output: hp2xx draws exactly the part of a drawing that lies within the pen's reach.
TEST_F(HpglHp2xx, ClippedDrawingMatchesTheClippedRaster) {
  PlotPage page = drawing(297, 210, 2);  // its frame runs outside the 7475A's reach, its diagonals across it
  page.strokes.push_back({{{2, 2}, {295, 208}}, 1});
  page.strokes.push_back({{{295, 2}, {150, 105}, {2, 208}}, 2});
  HpglOptions clip;
  clip.clip = true;
  const Ink actual = hp2xx_ink(to_hpgl(page, *hpgl_profile_by_name("hp7475a"), clip), dir_);
  // Expected: the same strokes, clipped by cairo to the reachable page area x 10–284.7, y 13.9–206 mm.
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1200, 850);
  cairo_t* cr = cairo_create(s);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_scale(cr, kPxPerMm, kPxPerMm);
  cairo_rectangle(cr, 10 - 0.1, 210 - 4 - 7721 * 0.02488 - 0.1, 11040 * 0.02488 + 0.2, 7721 * 0.02488 + 0.2);
  cairo_clip(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0 / kPxPerMm);
  for (const PlotStroke& stroke : page.strokes) {
    for (std::size_t i = 0; i < stroke.points.size(); ++i)
      (i ? cairo_line_to : cairo_move_to)(cr, stroke.points[i].x, stroke.points[i].y);
    cairo_stroke(cr);
  }
  cairo_destroy(cr);
  const Ink expected = ink_of(s);
  cairo_surface_destroy(s);
  expect_agreement(compare_ink(expected, actual));
}

}  // namespace
}  // namespace hlr
