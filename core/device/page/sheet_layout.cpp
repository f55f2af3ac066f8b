#include "core/device/page/sheet_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/tolerance.hpp"

namespace hlr {

double world_per_picture_unit(const Camera& camera, double fallback_depth) {
  if (camera.projection == Projection::Orthographic) return 1 / camera.focal;
  const double depth = camera.target_depth > 0 ? camera.target_depth
                       : fallback_depth > 0    ? fallback_depth
                                               : 1;
  return depth / camera.focal;
}

double iso_scale_at_most(double mm_per_unit) {
  const double decade = std::pow(10.0, std::floor(std::log10(mm_per_unit)));
  double best = decade;
  for (const double step : {2.0, 5.0, 10.0})
    if (step * decade <= mm_per_unit * (1 + Tolerance::kIsoScaleRelative)) best = step * decade;
  return best;
}

std::string scale_ratio_text(double mm_per_unit) {
  const auto number = [](double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", x);
    return std::string(buf);
  };
  if (mm_per_unit >= 1) return number(mm_per_unit) + ":1";
  return "1:" + number(1 / mm_per_unit);
}

namespace {

// The room a view's reach may take at scale s: s·reach ≤ room, a bound on s where reach > 0.
double bound(double room, double reach) {
  return reach > 0 ? room / reach : std::numeric_limits<double>::infinity();
}

// How far view a (at scale s, or its own) and view b reach towards each other, along x and y: each is
// {fixed mm, mm per unit of s}. For a left of b (or above it): a's right (bottom, with its label) and b's
// left (top).
struct Reach {
  double fixed = 0, per_scale = 0;
};
void add_reach(Reach& r, const SheetViewFit& v, double towards) {
  if (v.mm_per_unit)
    r.fixed += *v.mm_per_unit * towards;
  else
    r.per_scale += towards;
}

}  // namespace

double fitted_sheet_scale(const std::vector<SheetViewFit>& views, const PageSpec& spec,
                          const Rect2& keep_out) {
  if (spec.mm_per_unit) return *spec.mm_per_unit;
  const double m = spec.margin_mm, w = spec.paper.width_mm, h = spec.paper.height_mm;
  const Rect2 inside{m, m, w - m, h - m};
  double scale = std::numeric_limits<double>::infinity();
  const auto limit = [&](double s) {
    if (s > 0) scale = std::min(scale, s);  // a bound no scale meets is left to the caller's warnings
  };
  for (std::size_t i = 0; i < views.size(); ++i) {
    const SheetViewFit& v = views[i];
    if (v.mm_per_unit || v.extent.empty()) continue;
    const Point2 p = v.at_mm;
    if (!(p.x > inside.xmin && p.x < inside.xmax && p.y > inside.ymin && p.y < inside.ymax)) continue;
    // Inside the margins (page y grows downwards; the label sits below the drawing).
    limit(bound(inside.xmax - p.x, v.extent.xmax));
    limit(bound(p.x - inside.xmin, -v.extent.xmin));
    limit(bound(p.y - inside.ymin, v.extent.ymax));
    limit(bound(inside.ymax - p.y - v.label_band_mm, -v.extent.ymin));
    // Clear of the title block: to its left or above it.
    if (!keep_out.empty() && !keep_out.contains(p)) {
      const double left = p.x < keep_out.xmin ? bound(keep_out.xmin - kViewGapMm - p.x, v.extent.xmax) : 0;
      const double above =
          p.y < keep_out.ymin ? bound(keep_out.ymin - kViewGapMm - v.label_band_mm - p.y, -v.extent.ymin) : 0;
      limit(std::max(left, above));
    }
    // Clear of every other view: apart along x or along y, whichever allows more.
    for (std::size_t j = 0; j < views.size(); ++j) {
      const SheetViewFit& o = views[j];
      if (j == i || o.extent.empty() || (!o.mm_per_unit && j < i)) continue;  // fitted pairs once
      const double dx = o.at_mm.x - p.x, dy = o.at_mm.y - p.y;
      if (dx == 0 && dy == 0) continue;  // one point: drawn over one another on purpose
      const SheetViewFit& west = dx >= 0 ? v : o;
      const SheetViewFit& east = dx >= 0 ? o : v;
      const SheetViewFit& north = dy >= 0 ? v : o;
      const SheetViewFit& south = dy >= 0 ? o : v;
      Reach x, y;
      add_reach(x, west, west.extent.xmax);
      add_reach(x, east, -east.extent.xmin);
      add_reach(y, north, -north.extent.ymin);
      add_reach(y, south, south.extent.ymax);
      const double sx = bound(std::abs(dx) - kViewGapMm - x.fixed, x.per_scale);
      const double sy = bound(std::abs(dy) - kViewGapMm - north.label_band_mm - y.fixed, y.per_scale);
      limit(std::max(dx == 0 ? 0 : sx, dy == 0 ? 0 : sy));
    }
  }
  if (!std::isfinite(scale) || !(scale > 0)) return 1;
  return iso_scale_at_most(scale);
}

PageLayout view_layout(const Paper& paper, Point2 at_mm, double mm_per_unit) {  // per picture unit
  PageLayout layout;
  layout.page_width_mm = paper.width_mm;
  layout.page_height_mm = paper.height_mm;
  layout.scale = mm_per_unit;
  // to_page_mm((0, 0)) = at_mm.
  layout.picture_centre = {(0.5 * paper.width_mm - at_mm.x) / mm_per_unit,
                           (at_mm.y - 0.5 * paper.height_mm) / mm_per_unit};
  return layout;
}

SheetFrame sheet_frame(const PageSpec& spec) {
  const double m = spec.margin_mm, w = spec.paper.width_mm, h = spec.paper.height_mm;
  SheetFrame out;
  out.frame = {m, m, w - m, h - m};
  const double block_w = std::min(120.0, 0.5 * out.frame.width()), block_h = 16;
  if (block_w >= 50 && out.frame.height() >= 4 * block_h)
    out.title_block = {out.frame.xmax - block_w, out.frame.ymax - block_h, out.frame.xmax, out.frame.ymax};
  else
    out.title_block = Rect2::none();
  return out;
}

}  // namespace hlr
