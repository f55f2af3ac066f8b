#include "core/device/page/dimension_strokes.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/device/page/stroke_text.hpp"
#include "core/format_number.hpp"
#include "core/tolerance.hpp"

namespace hlr {

std::string dimension_value_text(double value, int precision) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", precision, value);
  std::string out = buf;
  if (out.find('.') != std::string::npos) {
    while (out.back() == '0') out.pop_back();
    if (out.back() == '.') out.pop_back();
  }
  if (out == "-0") out = "0";
  return out;
}

DimensionDrawing dimension_strokes(const PageDimension& d, const Camera& camera, const PageLayout& layout) {
  DimensionDrawing out;
  if (camera.projection == Projection::Perspective &&
      (camera.view(d.from).z <= camera.near_depth || camera.view(d.to).z <= camera.near_depth)) {
    out.problem = "a point lies behind the view's camera";
    return out;
  }
  Point2 a = layout.to_page_mm(camera.project(d.from)), b = layout.to_page_mm(camera.project(d.to));
  const Vector3 delta = d.to - d.from;
  // The page direction the dimension runs along, and what it measures.
  Vector2 u;
  switch (d.direction) {
    case DimensionDirection::Aligned:
      u = b - a;
      out.value = length(delta);
      break;
    case DimensionDirection::Horizontal:
    case DimensionDirection::Vertical: {
      const bool across = d.direction == DimensionDirection::Horizontal;
      const Vector3 axis = camera.viewFromWorld.row(across ? 0 : 1);
      out.value = std::abs(dot(delta, axis)) / length(axis);
      u = across ? Vector2{b.x - a.x, 0} : Vector2{0, b.y - a.y};
      break;
    }
  }
  const double span = length(u);
  if (!(span >= Tolerance::kDimensionMinSpanMm)) {
    out.problem = "its points fall together in this view (less than " +
                  format_mm_for_message(Tolerance::kDimensionMinSpanMm) + " mm apart along the dimension)";
    return out;
  }
  u = (1 / span) * u;
  // Read from left to right, or from the bottom up: the value's letters then stand upright.
  constexpr double upright = Tolerance::kDimensionUprightSlack;
  if (u.x < -upright || (std::abs(u.x) <= upright && u.y > 0)) {
    std::swap(a, b);
    u = -1 * u;
  }
  const Vector2 n{u.y, -u.x};  // up from the line (left of an upright one), page y growing downwards
  // The dimension line, offset from the farther-out point (so both extension lines reach it); heights
  // are measured along n.
  const double ha = dot(a - Point2{0, 0}, n), hb = dot(b - Point2{0, 0}, n);
  const double level = d.offset_mm >= 0 ? std::max(ha, hb) + d.offset_mm : std::min(ha, hb) + d.offset_mm;
  const Point2 a1 = a + (level - ha) * n;
  const Point2 b1 = b + (level - hb) * n;
  const Vector2 out_dir = d.offset_mm >= 0 ? n : -1 * n;  // from the points towards the dimension line
  for (const auto& [p, p1] : {std::pair{a, a1}, std::pair{b, b1}}) {
    if (distance(p, p1) > kExtensionGapMm)
      out.strokes.push_back({p + kExtensionGapMm * out_dir, p1 + kExtensionOverMm * out_dir});
  }
  out.strokes.push_back({a1, b1});
  const double t = kArrowHalfAngleDeg * std::numbers::pi / 180;
  const Vector2 w1 = std::cos(t) * u + std::sin(t) * n, w2 = std::cos(t) * u - std::sin(t) * n;
  out.strokes.push_back({a1 + kArrowMm * w1, a1, a1 + kArrowMm * w2});
  out.strokes.push_back({b1 + -kArrowMm * w1, b1, b1 + -kArrowMm * w2});

  out.text = d.text ? *d.text : dimension_value_text(out.value, d.precision);
  // The value centred over the line (on the side away from the points), turned with it.
  const double width = stroke_text_width_mm(out.text, d.cap_mm);
  const Point2 mid = lerp(a1, b1, 0.5);
  const double side = d.offset_mm >= 0 ? 1 : -1;
  const Point2 base = mid + (side > 0 ? 1.0 : 1.0 + d.cap_mm) * side * n + -0.5 * width * u;
  for (std::vector<Point2> stroke : stroke_text(out.text, {0, 0}, d.cap_mm)) {
    // Letters are drawn with x along the baseline and up as −y: x ↦ u, −y ↦ n.
    for (Point2& p : stroke) p = base + p.x * u + -p.y * n;
    out.strokes.push_back(std::move(stroke));
  }
  return out;
}

}  // namespace hlr
