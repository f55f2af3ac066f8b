#include "core/device/page/dimension_strokes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <tuple>
#include <utility>

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

std::optional<DimensionUnit> dimension_unit_named(const std::string& name) {
  if (name == "mm") return DimensionUnit::Mm;
  if (name == "cm") return DimensionUnit::Cm;
  if (name == "m") return DimensionUnit::M;
  if (name == "in") return DimensionUnit::In;
  return std::nullopt;
}

std::string dimension_distance_text(double world, DimensionUnit unit, int precision) {
  switch (unit) {
    case DimensionUnit::Mm:
      return dimension_value_text(world, precision);
    case DimensionUnit::Cm:
      return dimension_value_text(world / 10, precision) + " cm";
    case DimensionUnit::M:
      return dimension_value_text(world / 1000, precision) + " m";
    case DimensionUnit::In:
      return dimension_value_text(world / 25.4, precision) + "\"";
  }
  return dimension_value_text(world, precision);
}

namespace {

// The value's letters with their baseline starting at `base`, running along u, up along n (page y grows
// downwards; letters are drawn with x along the baseline and up as −y).
void append_value_text(DimensionDrawing& out, double cap_mm, Point2 base, Vector2 u, Vector2 n) {
  for (std::vector<Point2> stroke : stroke_text(out.text, {0, 0}, cap_mm)) {
    for (Point2& p : stroke) p = base + p.x * u + -p.y * n;
    out.strokes.push_back(std::move(stroke));
  }
}

// Read from left to right, or from the bottom up: the letters then stand upright.
bool reads_backwards(Vector2 u) {
  constexpr double upright = Tolerance::kDimensionUprightSlack;
  return u.x < -upright || (std::abs(u.x) <= upright && u.y > 0);
}

bool behind_eye(const Camera& camera, Point3 p) {
  return camera.projection == Projection::Perspective && camera.view(p).z <= camera.near_depth;
}

// An open arrowhead at `tip`, its two strokes `back` of it (a unit vector) at ±15°.
std::vector<Point2> arrowhead(Point2 tip, Vector2 back) {
  const double t = kArrowHalfAngleDeg * std::numbers::pi / 180;
  const Vector2 side{back.y, -back.x};
  return {tip + kArrowMm * (std::cos(t) * back + std::sin(t) * side), tip,
          tip + kArrowMm * (std::cos(t) * back - std::sin(t) * side)};
}

DimensionDrawing angle_strokes(const PageDimension& d, const Camera& camera, const PageLayout& layout) {
  DimensionDrawing out;
  const Point3 vertex = *d.vertex;
  if (behind_eye(camera, vertex) || behind_eye(camera, d.from) || behind_eye(camera, d.to)) {
    out.problem = "a point lies behind the view's camera";
    return out;
  }
  const Vector3 leg_a = d.from - vertex, leg_b = d.to - vertex;
  if (!(length(leg_a) > 0) || !(length(leg_b) > 0)) {
    out.problem = "a leg of the angle has no length (a point is the vertex)";
    return out;
  }
  out.value = std::atan2(length(cross(leg_a, leg_b)), dot(leg_a, leg_b)) * 180 / std::numbers::pi;
  const Point2 v = layout.to_page_mm(camera.project(vertex));
  const Point2 a = layout.to_page_mm(camera.project(d.from)), b = layout.to_page_mm(camera.project(d.to));
  constexpr double min_span = Tolerance::kDimensionMinSpanMm;
  if (!(distance(v, a) >= min_span) || !(distance(v, b) >= min_span)) {
    out.problem =
        "a leg falls on the vertex in this view (less than " + format_mm_for_message(min_span) + " mm long)";
    return out;
  }
  // The arc runs from leg a to leg b the short way round in the picture.
  const double ta = std::atan2(a.y - v.y, a.x - v.x), tb = std::atan2(b.y - v.y, b.x - v.x);
  const double sweep = std::remainder(tb - ta, 2 * std::numbers::pi);
  const double r = d.radius_mm;
  if (!(std::abs(sweep) * r >= min_span)) {
    out.problem = "its legs fall on one line in this view";
    return out;
  }
  const auto dir = [](double t) { return Vector2{std::cos(t), std::sin(t)}; };
  const double step = 2 * std::acos(1 - std::min(Tolerance::kDimensionArcChordMm / r, 1.0));
  const int pieces = std::max(2, static_cast<int>(std::ceil(std::abs(sweep) / step)));
  std::vector<Point2> arc;
  for (int i = 0; i <= pieces; ++i) arc.push_back(v + r * dir(ta + sweep * i / pieces));
  // A leg shorter than the radius is drawn on to the arc; a leg asked for is drawn from the vertex.
  for (const auto& [p, t, whole] : {std::tuple{a, ta, d.extend_from}, std::tuple{b, tb, d.extend_to}}) {
    if (whole)
      out.strokes.push_back({v, v + (r + kExtensionOverMm) * dir(t)});
    else if (r > distance(v, p) + kExtensionGapMm)
      out.strokes.push_back({p + kExtensionGapMm * dir(t), v + (r + kExtensionOverMm) * dir(t)});
  }
  // The arrowheads point out along the arc at its ends.
  const double turn = sweep > 0 ? 1 : -1;
  const Vector2 along_a = turn * Vector2{-std::sin(ta), std::cos(ta)};   // into the arc at a
  const Vector2 along_b = -turn * Vector2{-std::sin(tb), std::cos(tb)};  // into the arc at b
  out.strokes.push_back(arc);
  out.strokes.push_back(arrowhead(arc.front(), along_a));
  out.strokes.push_back(arrowhead(arc.back(), along_b));

  out.text = d.text ? *d.text : dimension_value_text(out.value, d.precision) + "\u00b0";
  // Outside the arc's middle, along its tangent.
  const Vector2 e = dir(ta + sweep / 2);
  Vector2 u{-e.y, e.x};
  if (reads_backwards(u)) u = -1 * u;
  const Vector2 n{u.y, -u.x};  // the letters' up: outward (along e) or inward
  const double width = stroke_text_width_mm(out.text, d.cap_mm);
  const Point2 base = v + (r + (dot(n, e) > 0 ? 1.0 : 1.0 + d.cap_mm)) * e + -0.5 * width * u;
  append_value_text(out, d.cap_mm, base, u, n);
  return out;
}

}  // namespace

DimensionDrawing dimension_strokes(const PageDimension& d, const Camera& camera, const PageLayout& layout) {
  if (d.vertex) return angle_strokes(d, camera, layout);
  DimensionDrawing out;
  if (behind_eye(camera, d.from) || behind_eye(camera, d.to)) {
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
  if (reads_backwards(u)) {
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
  out.strokes.push_back(arrowhead(a1, u));
  out.strokes.push_back(arrowhead(b1, -1 * u));

  out.text = d.text ? *d.text : dimension_distance_text(out.value, d.unit, d.precision);
  // The value centred over the line (on the side away from the points), turned with it.
  const double width = stroke_text_width_mm(out.text, d.cap_mm);
  const Point2 mid = lerp(a1, b1, 0.5);
  const double side = d.offset_mm >= 0 ? 1 : -1;
  const Point2 base = mid + (side > 0 ? 1.0 : 1.0 + d.cap_mm) * side * n + -0.5 * width * u;
  append_value_text(out, d.cap_mm, base, u, n);
  return out;
}

}  // namespace hlr
