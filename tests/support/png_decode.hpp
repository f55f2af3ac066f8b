// Reads a PNG file's bytes back with libpng's own reader (the tests of core/device/formats/png_encoder.cpp
// and of the PNG device): its pixels as straight RGBA, and the colour type its header declares.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace hlr::test {

struct DecodedPng {
  int colour_type = -1;  // PNG_COLOR_TYPE_GRAY (0), _RGB (2), _GRAY_ALPHA (4), _RGB_ALPHA (6)
  long width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // straight (not premultiplied), row by row
  const std::uint8_t* at(long x, long y) const {
    return &rgba[static_cast<std::size_t>(4 * (y * width + x))];
  }
};

// Adds a test failure (and returns what it has) when libpng cannot read the bytes.
DecodedPng decode_png(const std::string& bytes);

}  // namespace hlr::test
