// Comparing two raster drawings that should show the same lines, independently of their scale and
// placement: each image becomes an ink mask (dark pixels, composited over white), both are normalised by
// their inked bounding box with one scale for both axes (so an aspect or orientation error still shows),
// and each inked pixel must find ink within a few pixels in the other. Used to check hp2xx's rendering of
// our HPGL against a cairo raster (tests/core/device/formats/hpgl_hp2xx_test.cpp,
// tests/runtime/pipeline/devices_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

typedef struct _cairo_surface cairo_surface_t;  // as cairo.h declares it

namespace hlr::test {

struct Ink {
  int w = 0, h = 0;
  std::vector<std::uint8_t> on;
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;  // inked bounding box
  std::size_t count = 0;

  bool at(int x, int y) const;
  // Ink within the (2r+1)² square around the pixel nearest (fx, fy).
  bool near(double fx, double fy, int r) const;
};

// The dark pixels (luminance below 160 of 255, composited over white) of an RGB24 or ARGB32 image surface.
Ink ink_of(cairo_surface_t* surface);
// The same of a PNG file; an Ink with w == 0 when cairo cannot read it.
Ink ink_of_png(const std::filesystem::path& png);

struct Agreement {
  bool aspect_ok = false;  // the boxes' heights agree (within 3 px) at the scale of their widths
  double expected_found = 0, actual_found = 0;  // fractions of inked pixels with ink within `radius` opposite
};

Agreement compare_ink(const Ink& expected, const Ink& actual, int radius = 2);

bool have_hp2xx();

// hp2xx's rendering of `hpgl` at `dpi` and true size (-t), every pen black, written to `dir`/in.hpgl and
// read back from `dir`/out.png. A failure of hp2xx is a test failure; the Ink is then empty.
Ink hp2xx_ink(const std::string& hpgl, const std::filesystem::path& dir, int dpi = 100);

}  // namespace hlr::test
