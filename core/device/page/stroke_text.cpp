#include "core/device/page/stroke_text.hpp"

#include "core/device/page/stroke_glyphs.hpp"

namespace hlr {
namespace {

constexpr double kCapUnits = 21;  // the simplex fonts' cap height in font units

}  // namespace

std::vector<std::vector<Point2>> stroke_text(std::string_view text, Point2 baseline_start,
                                             double cap_height_mm) {
  const double unit = cap_height_mm / kCapUnits;
  std::vector<std::vector<Point2>> strokes;
  double x = baseline_start.x;
  for (const char32_t c : decode_utf8(text)) {
    const StrokeGlyph g = stroke_glyph(c);
    for (const std::vector<Point2>& path : g.strokes) {
      std::vector<Point2>& stroke = strokes.emplace_back();
      stroke.reserve(path.size());
      for (const Point2& p : path)  // font y grows up, the page's down
        stroke.push_back({x + unit * p.x, baseline_start.y - unit * p.y});
    }
    x += unit * g.width;
  }
  return strokes;
}

double stroke_text_width_mm(std::string_view text, double cap_height_mm) {
  double units = 0;
  for (const char32_t c : decode_utf8(text)) units += stroke_glyph(c).width;
  return units * cap_height_mm / kCapUnits;
}

}  // namespace hlr
