// The HPGL device against an independent interpreter: hp2xx (Debian's 3.4.4) renders our HPGL to PNG, and
// the test rasterises the same PlotPage strokes itself with cairo, placed by the documented convention
// (page y down; a portrait page turned 90° counter-clockwise onto a landscape sheet). hp2xx crops to the
// drawing and knows only the nominal 0.025 mm unit, so both rasters are normalised by their inked bounding
// box with one scale for both axes (an aspect or orientation error still shows), then compared: nearly
// every inked pixel of each must have ink within 2 px in the other.
#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "core/device/hpgl_device.hpp"

namespace hlr {
namespace {

namespace fs = std::filesystem;

constexpr double kPxPerMm = 100 / 25.4;  // hp2xx -d 100 at true size

struct Ink {
  int w = 0, h = 0;
  std::vector<std::uint8_t> on;
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;  // inked bounding box
  std::size_t count = 0;

  bool at(int x, int y) const {
    return x >= 0 && y >= 0 && x < w && y < h && on[static_cast<std::size_t>(y) * w + x];
  }
  bool near(double fx, double fy, int r) const {
    const int cx = static_cast<int>(std::lround(fx)), cy = static_cast<int>(std::lround(fy));
    for (int y = cy - r; y <= cy + r; ++y)
      for (int x = cx - r; x <= cx + r; ++x)
        if (at(x, y)) return true;
    return false;
  }
};

Ink ink_of(cairo_surface_t* s) {
  Ink ink;
  cairo_surface_flush(s);
  ink.w = cairo_image_surface_get_width(s);
  ink.h = cairo_image_surface_get_height(s);
  const cairo_format_t format = cairo_image_surface_get_format(s);
  const int stride = cairo_image_surface_get_stride(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  ink.on.assign(static_cast<std::size_t>(ink.w) * ink.h, 0);
  for (int y = 0; y < ink.h; ++y) {
    for (int x = 0; x < ink.w; ++x) {
      const std::uint32_t px = *reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x);
      const double a = format == CAIRO_FORMAT_ARGB32 ? ((px >> 24) & 0xff) / 255.0 : 1.0;
      // Premultiplied over white: luminance of the composited pixel.
      const double r = ((px >> 16) & 0xff) + 255 * (1 - a), g = ((px >> 8) & 0xff) + 255 * (1 - a),
                   b = (px & 0xff) + 255 * (1 - a);
      if (0.299 * r + 0.587 * g + 0.114 * b < 160) {
        ink.on[static_cast<std::size_t>(y) * ink.w + x] = 1;
        ++ink.count;
        ink.x0 = std::min(ink.x0, x), ink.x1 = std::max(ink.x1, x);
        ink.y0 = std::min(ink.y0, y), ink.y1 = std::max(ink.y1, y);
      }
    }
  }
  return ink;
}

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

bool have_hp2xx() { return std::system("command -v hp2xx >/dev/null 2>&1") == 0; }

// hp2xx's rendering of `hpgl`, at true size, every pen black.
Ink hp2xx_ink(const std::string& hpgl, const fs::path& dir) {
  {
    std::ofstream out(dir / "in.hpgl", std::ios::binary);
    out << hpgl;
  }
  const std::string cmd =
      "cd '" + dir.string() + "' && hp2xx -q -m png -d 100 -t -c 11111111 -f out.png in.hpgl";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  cairo_surface_t* s = cairo_image_surface_create_from_png((dir / "out.png").c_str());
  EXPECT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
  Ink ink = cairo_surface_status(s) == CAIRO_STATUS_SUCCESS ? ink_of(s) : Ink{};
  cairo_surface_destroy(s);
  return ink;
}

struct Agreement {
  bool aspect_ok = false;
  double expected_found = 0, actual_found = 0;  // fractions of inked pixels with ink within 2 px opposite
};

Agreement compare(const Ink& e, const Ink& a) {
  Agreement g;
  if (e.count == 0 || a.count == 0) return g;
  const double s = static_cast<double>(a.x1 - a.x0) / (e.x1 - e.x0);
  g.aspect_ok = std::fabs((a.y1 - a.y0) - s * (e.y1 - e.y0)) <= 3;
  std::size_t found = 0;
  for (int y = e.y0; y <= e.y1; ++y)
    for (int x = e.x0; x <= e.x1; ++x)
      if (e.at(x, y) && a.near(a.x0 + (x - e.x0) * s, a.y0 + (y - e.y0) * s, 2)) ++found;
  g.expected_found = static_cast<double>(found) / e.count;
  found = 0;
  for (int y = a.y0; y <= a.y1; ++y)
    for (int x = a.x0; x <= a.x1; ++x)
      if (a.at(x, y) && e.near(e.x0 + (x - a.x0) / s, e.y0 + (y - a.y0) / s, 2)) ++found;
  g.actual_found = static_cast<double>(found) / a.count;
  return g;
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
    if (!have_hp2xx()) GTEST_SKIP() << "hp2xx is not installed";
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
    return compare(expected, actual);
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
  expect_agreement(compare(expected, actual));
}

}  // namespace
}  // namespace hlr
