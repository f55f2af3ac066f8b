#include "tests/support/raster_compare.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace hlr::test {

bool Ink::at(int x, int y) const {
  return x >= 0 && y >= 0 && x < w && y < h && on[static_cast<std::size_t>(y) * w + x];
}

bool Ink::near(double fx, double fy, int r) const {
  const int cx = static_cast<int>(std::lround(fx)), cy = static_cast<int>(std::lround(fy));
  for (int y = cy - r; y <= cy + r; ++y)
    for (int x = cx - r; x <= cx + r; ++x)
      if (at(x, y)) return true;
  return false;
}

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

Ink ink_of_png(const std::filesystem::path& png) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(png.c_str());
  Ink ink = cairo_surface_status(s) == CAIRO_STATUS_SUCCESS ? ink_of(s) : Ink{};
  cairo_surface_destroy(s);
  return ink;
}

Agreement compare_ink(const Ink& e, const Ink& a, int radius) {
  Agreement g;
  if (e.count == 0 || a.count == 0) return g;
  const double s = static_cast<double>(a.x1 - a.x0) / (e.x1 - e.x0);
  g.aspect_ok = std::fabs((a.y1 - a.y0) - s * (e.y1 - e.y0)) <= 3;
  std::size_t found = 0;
  for (int y = e.y0; y <= e.y1; ++y)
    for (int x = e.x0; x <= e.x1; ++x)
      if (e.at(x, y) && a.near(a.x0 + (x - e.x0) * s, a.y0 + (y - e.y0) * s, radius)) ++found;
  g.expected_found = static_cast<double>(found) / e.count;
  found = 0;
  for (int y = a.y0; y <= a.y1; ++y)
    for (int x = a.x0; x <= a.x1; ++x)
      if (a.at(x, y) && e.near(e.x0 + (x - a.x0) / s, e.y0 + (y - a.y0) / s, radius)) ++found;
  g.actual_found = static_cast<double>(found) / a.count;
  return g;
}

bool have_hp2xx() { return std::system("command -v hp2xx >/dev/null 2>&1") == 0; }

Ink hp2xx_ink(const std::string& hpgl, const std::filesystem::path& dir, int dpi) {
  {
    std::ofstream out(dir / "in.hpgl", std::ios::binary);
    out << hpgl;
  }
  std::filesystem::remove(dir / "out.png");
  const std::string cmd = "cd '" + dir.string() + "' && hp2xx -q -m png -d " + std::to_string(dpi) +
                          " -t -c 11111111 -f out.png in.hpgl";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const Ink ink = ink_of_png(dir / "out.png");
  EXPECT_GT(ink.w, 0) << "cairo cannot read " << (dir / "out.png");
  return ink;
}

}  // namespace hlr::test
