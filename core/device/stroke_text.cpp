#include "core/device/stroke_text.hpp"

#include <memory>
#include <string>

#include "core/device/atomic_file.hpp"

extern "C" {  // the C library's header has no C++ guard
#include <hersheyfont.h>
}

namespace hlr {
namespace {

constexpr double kCapUnits = 21;  // the simplex fonts' cap height in font units
constexpr const char* kFontName = "futural";

struct FontFree {
  void operator()(hershey_font* font) const { hershey_font_free(font); }
};

// Loaded once, on first use, by whichever thread gets there first; read-only afterwards.
hershey_font& font() {
  static const std::unique_ptr<hershey_font, FontFree> loaded(hershey_font_load(kFontName));
  if (!loaded)
    throw DeviceError(
        std::string("cannot load the single-stroke font '") + kFontName +
        "' (install Debian's hershey-fonts-data), or draw text as outlines with --text outline");
  return *loaded;
}

const hershey_glyph& glyph(hershey_font& f, char c) {
  const auto byte = static_cast<unsigned char>(c);
  const char drawn = byte >= 0x20 && byte < 0x7f ? c : '?';
  return *hershey_font_glyph(&f, static_cast<unsigned char>(drawn));
}

}  // namespace

std::vector<std::vector<Point2>> stroke_text(std::string_view text, Point2 baseline_start,
                                             double cap_height_mm) {
  hershey_font& f = font();
  const double unit = cap_height_mm / kCapUnits;
  std::vector<std::vector<Point2>> strokes;
  double x = baseline_start.x;
  for (const char c : text) {
    const hershey_glyph& g = glyph(f, c);
    for (const hershey_path* path = g.paths; path; path = path->next) {
      if (path->nverts < 2) continue;
      std::vector<Point2>& stroke = strokes.emplace_back();
      stroke.reserve(path->nverts);
      for (unsigned short i = 0; i < path->nverts; ++i)  // font y grows up, the page's down
        stroke.push_back({x + unit * path->verts[i].x, baseline_start.y - unit * path->verts[i].y});
    }
    x += unit * g.width;
  }
  return strokes;
}

double stroke_text_width_mm(std::string_view text, double cap_height_mm) {
  hershey_font& f = font();
  double units = 0;
  for (const char c : text) units += glyph(f, c).width;
  return units * cap_height_mm / kCapUnits;
}

}  // namespace hlr
