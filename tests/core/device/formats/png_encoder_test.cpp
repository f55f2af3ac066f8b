#include "core/device/formats/png_encoder.hpp"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "tests/support/png_decode.hpp"

namespace hlr {
namespace {

using Decoded = test::DecodedPng;
Decoded decode(const std::string& bytes) { return test::decode_png(bytes); }

std::vector<int> pixel(const Decoded& d, long x, long y) {
  const std::uint8_t* p = &d.rgba[static_cast<std::size_t>(4 * (y * d.width + x))];
  return {p[0], p[1], p[2], p[3]};
}

TEST(PngEncoder, InkBecomesGreyOnWhite) {
  // 3 × 2 pixels, rows padded to 4 bytes as cairo pads them.
  const std::uint8_t ink[] = {0, 255, 128, 9, 64, 1, 200, 9};
  const std::string bytes = encode_png({ink, 3, 2, 4, PngPixels::InkGrey});
  const Decoded d = decode(bytes);
  EXPECT_EQ(d.colour_type, PNG_COLOR_TYPE_GRAY);
  ASSERT_EQ(d.width, 3);
  ASSERT_EQ(d.height, 2);
  EXPECT_EQ(pixel(d, 0, 0), (std::vector<int>{255, 255, 255, 255}));
  EXPECT_EQ(pixel(d, 1, 0), (std::vector<int>{0, 0, 0, 255}));
  EXPECT_EQ(pixel(d, 2, 0), (std::vector<int>{127, 127, 127, 255}));
  EXPECT_EQ(pixel(d, 0, 1), (std::vector<int>{191, 191, 191, 255}));
  EXPECT_EQ(pixel(d, 2, 1), (std::vector<int>{55, 55, 55, 255}));
}

TEST(PngEncoder, InkWithoutPaperIsBlackWithAlpha) {
  const std::uint8_t ink[] = {0, 255, 100, 0};
  const Decoded d = decode(encode_png({ink, 3, 1, 4, PngPixels::InkGreyAlpha}));
  EXPECT_EQ(d.colour_type, PNG_COLOR_TYPE_GRAY_ALPHA);
  EXPECT_EQ(pixel(d, 0, 0)[3], 0);
  EXPECT_EQ(pixel(d, 1, 0), (std::vector<int>{0, 0, 0, 255}));
  EXPECT_EQ(pixel(d, 2, 0), (std::vector<int>{0, 0, 0, 100}));
}

TEST(PngEncoder, CairoWordsBecomeRgb) {
  const std::uint32_t words[] = {0xff102030u, 0x00ff0000u};  // xRGB: the x byte is ignored
  const Decoded d =
      decode(encode_png({reinterpret_cast<const std::uint8_t*>(words), 2, 1, 8, PngPixels::Rgb}));
  EXPECT_EQ(d.colour_type, PNG_COLOR_TYPE_RGB);
  EXPECT_EQ(pixel(d, 0, 0), (std::vector<int>{0x10, 0x20, 0x30, 255}));
  EXPECT_EQ(pixel(d, 1, 0), (std::vector<int>{255, 0, 0, 255}));
}

TEST(PngEncoder, PremultipliedWordsBecomeStraightRgba) {
  // Half-transparent red premultiplied is 0x80800000; fully clear is all zero.
  const std::uint32_t words[] = {0x80800000u, 0x00000000u, 0xff00ff00u};
  const Decoded d =
      decode(encode_png({reinterpret_cast<const std::uint8_t*>(words), 3, 1, 12, PngPixels::Rgba}));
  EXPECT_EQ(d.colour_type, PNG_COLOR_TYPE_RGB_ALPHA);
  EXPECT_EQ(pixel(d, 0, 0), (std::vector<int>{255, 0, 0, 128}));
  EXPECT_EQ(pixel(d, 1, 0)[3], 0);
  EXPECT_EQ(pixel(d, 2, 0), (std::vector<int>{0, 255, 0, 255}));
}

TEST(PngEncoder, LargeBlankRasterCompressesToLittle) {
  // A blank A4 page at 150 dpi: runs of white are what the deflate setting is chosen for.
  const long w = 1754, h = 1240;
  const std::vector<std::uint8_t> ink(static_cast<std::size_t>(w * h), 0);
  const std::string bytes = encode_png({ink.data(), w, h, w, PngPixels::InkGrey});
  const Decoded d = decode(bytes);
  EXPECT_EQ(d.width, w);
  EXPECT_EQ(pixel(d, w - 1, h - 1), (std::vector<int>{255, 255, 255, 255}));
  EXPECT_LT(bytes.size(), static_cast<std::size_t>(w * h) / 100);
}

}  // namespace
}  // namespace hlr
