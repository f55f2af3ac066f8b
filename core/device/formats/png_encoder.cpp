#include "core/device/formats/png_encoder.hpp"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace hlr {
namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
}
void flush_nothing(png_structp) {}
// libpng is C: an error cannot unwind through it as an exception, so it jumps back to encode_png(),
// which throws with the message kept here.
struct ErrorText {
  char text[200] = "";
};
[[noreturn]] void fail(png_structp png, png_const_charp message) {
  auto* error = static_cast<ErrorText*>(png_get_error_ptr(png));
  std::snprintf(error->text, sizeof error->text, "%s", message);
  png_longjmp(png, 1);
}
void ignore_warning(png_structp, png_const_charp) {}

// Owns the libpng write structures.
struct PngWriter {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ErrorText error;
  PngWriter() {
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, fail, ignore_warning);
    if (!png) throw std::runtime_error("PNG: out of memory");
    info = png_create_info_struct(png);
    if (!info) {
      png_destroy_write_struct(&png, nullptr);
      throw std::runtime_error("PNG: out of memory");
    }
  }
  ~PngWriter() { png_destroy_write_struct(&png, &info); }
  PngWriter(const PngWriter&) = delete;
  PngWriter& operator=(const PngWriter&) = delete;
};

int channels(PngPixels p) {
  switch (p) {
    case PngPixels::InkGrey:
      return 1;
    case PngPixels::InkGreyAlpha:
      return 2;
    case PngPixels::Rgb:
      return 3;
    case PngPixels::Rgba:
      return 4;
  }
  return 4;
}

int colour_type(PngPixels p) {
  switch (p) {
    case PngPixels::InkGrey:
      return PNG_COLOR_TYPE_GRAY;
    case PngPixels::InkGreyAlpha:
      return PNG_COLOR_TYPE_GRAY_ALPHA;
    case PngPixels::Rgb:
      return PNG_COLOR_TYPE_RGB;
    case PngPixels::Rgba:
      return PNG_COLOR_TYPE_RGB_ALPHA;
  }
  return PNG_COLOR_TYPE_RGB_ALPHA;
}

std::uint8_t unpremultiply(std::uint32_t channel, std::uint32_t alpha) {
  return static_cast<std::uint8_t>((channel * 255 + alpha / 2) / alpha);
}

// One raster row as the PNG stores it.
void convert_row(const unsigned char* in, long width, PngPixels pixels, std::uint8_t* out) {
  switch (pixels) {
    case PngPixels::InkGrey:
      for (long x = 0; x < width; ++x) out[x] = static_cast<std::uint8_t>(255 - in[x]);
      return;
    case PngPixels::InkGreyAlpha:
      for (long x = 0; x < width; ++x) {
        out[2 * x] = 0;
        out[2 * x + 1] = in[x];
      }
      return;
    case PngPixels::Rgb:
      for (long x = 0; x < width; ++x) {
        std::uint32_t w;
        std::memcpy(&w, in + 4 * x, 4);
        out[3 * x] = static_cast<std::uint8_t>(w >> 16);
        out[3 * x + 1] = static_cast<std::uint8_t>(w >> 8);
        out[3 * x + 2] = static_cast<std::uint8_t>(w);
      }
      return;
    case PngPixels::Rgba:
      for (long x = 0; x < width; ++x) {
        std::uint32_t w;
        std::memcpy(&w, in + 4 * x, 4);
        const std::uint32_t a = w >> 24;
        std::uint8_t* o = out + 4 * x;
        if (a == 0) {
          o[0] = o[1] = o[2] = o[3] = 0;
        } else {
          o[0] = unpremultiply((w >> 16) & 0xff, a);
          o[1] = unpremultiply((w >> 8) & 0xff, a);
          o[2] = unpremultiply(w & 0xff, a);
          o[3] = static_cast<std::uint8_t>(a);
        }
      }
      return;
  }
}

// Writes the file into `bytes`; false if libpng failed (its message in w.error). Nothing here owns
// anything, so the jump back from an error skips no destructor.
bool write_png(PngWriter& w, const PngRaster& raster, std::uint8_t* row, std::string& bytes) {
  if (setjmp(png_jmpbuf(w.png))) return false;
  png_set_write_fn(w.png, &bytes, append_bytes, flush_nothing);
  png_set_IHDR(w.png, w.info, static_cast<png_uint_32>(raster.width), static_cast<png_uint_32>(raster.height),
               8, colour_type(raster.pixels), PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(w.png, 1);
  png_set_compression_strategy(w.png, Z_RLE);
  png_set_filter(w.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_write_info(w.png, w.info);
  for (long y = 0; y < raster.height; ++y) {
    convert_row(raster.data + y * raster.stride, raster.width, raster.pixels, row);
    png_write_row(w.png, row);
  }
  png_write_end(w.png, w.info);
  return true;
}

}  // namespace

std::string encode_png(const PngRaster& raster) {
  std::string bytes;
  std::vector<std::uint8_t> row(static_cast<std::size_t>(raster.width) * channels(raster.pixels));
  PngWriter w;
  if (!write_png(w, raster, row.data(), bytes)) throw std::runtime_error(std::string("PNG: ") + w.error.text);
  return bytes;
}

}  // namespace hlr
