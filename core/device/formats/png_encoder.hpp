// PNG files from a page cairo has rasterised: 8-bit grey, grey + alpha, RGB or RGBA, written by libpng
// with the deflate settings measured fastest for line drawings (bench/README.md, "PNG encoding"): no
// row filter and zlib's run-length strategy at level 1. A drawing is long runs of white broken by a few
// pixels of ink; runs are what it compresses, faster and smaller than zlib's default (level 6, adaptive
// filters) by 4× and 3×.
#pragma once

#include <cstddef>
#include <string>

namespace hlr {

// How the PNG stores a pixel, and how the raster given is read.
enum class PngPixels {
  InkGrey,       // from an A8 raster whose alpha is ink: grey = 255 − alpha (white paper)
  InkGreyAlpha,  // from an A8 raster: black ink, alpha = the raster's alpha (no paper)
  Rgb,           // from cairo's RGB24 (native-endian 0xXXRRGGBB words)
  Rgba,          // from cairo's ARGB32 (premultiplied, native-endian 0xAARRGGBB words)
};

struct PngRaster {
  const unsigned char* data = nullptr;
  long width = 0, height = 0;
  std::ptrdiff_t stride = 0;  // bytes from one row to the next
  PngPixels pixels = PngPixels::InkGrey;
};

// The PNG file's bytes. Throws std::runtime_error if libpng fails.
std::string encode_png(const PngRaster& raster);

}  // namespace hlr
