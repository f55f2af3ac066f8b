#include "tests/support/png_decode.hpp"

#include <gtest/gtest.h>
#include <png.h>

#include <cstring>

namespace hlr::test {

DecodedPng decode_png(const std::string& bytes) {
  DecodedPng d;
  if (bytes.size() > 25) d.colour_type = static_cast<unsigned char>(bytes[25]);  // IHDR's colour type
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) {
    ADD_FAILURE() << "libpng cannot read it: " << image.message;
    return d;
  }
  image.format = PNG_FORMAT_RGBA;
  d.width = image.width;
  d.height = image.height;
  d.rgba.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, d.rgba.data(), 0, nullptr))
    ADD_FAILURE() << "libpng cannot read it: " << image.message;
  return d;
}

}  // namespace hlr::test
