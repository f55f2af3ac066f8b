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
    // Inside the margins (page y grows downwards; the label sits below the drawing and its dimensions).
    const ViewMargins& d = v.dimensions;
    limit(bound(inside.xmax - p.x - d.right, v.extent.xmax));
    limit(bound(p.x - inside.xmin - d.left, -v.extent.xmin));
    limit(bound(p.y - inside.ymin - d.top, v.extent.ymax));
    limit(bound(inside.ymax - p.y - v.label_band_mm - d.bottom, -v.extent.ymin));
    // Clear of the title block: to its left or above it.
    if (!keep_out.empty() && !keep_out.contains(p)) {
      const double left =
          p.x < keep_out.xmin ? bound(keep_out.xmin - kViewGapMm - d.right - p.x, v.extent.xmax) : 0;
      const double above =
          p.y < keep_out.ymin
              ? bound(keep_out.ymin - kViewGapMm - v.label_band_mm - d.bottom - p.y, -v.extent.ymin)
              : 0;
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
      x.fixed += west.dimensions.right + east.dimensions.left;
      y.fixed += north.dimensions.bottom + south.dimensions.top;
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

namespace {

// The grid's columns (x) or rows (y): each one's extent in world units, the union of its views'.
struct GridBands {
  std::vector<double> lo, hi, band;   // per column or row; lo > hi: nothing drawn in it
  std::vector<double> before, after;  // dimensions' room: left and right of a column, above and below a row
  double world() const {
    double sum = 0;
    for (std::size_t i = 0; i < lo.size(); ++i) sum += std::max(0.0, hi[i] - lo[i]);
    return sum;
  }
  double bands() const {  // labels and dimensions: millimetres whatever the scale
    double sum = 0;
    for (std::size_t i = 0; i < band.size(); ++i) sum += band[i] + before[i] + after[i];
    return sum;
  }
};

GridBands grid_bands(const std::vector<GridViewFit>& views, bool columns) {
  GridBands out;
  for (const GridViewFit& v : views) {
    const auto i = static_cast<std::size_t>(columns ? v.column : v.row);
    if (i >= out.lo.size()) {
      out.lo.resize(i + 1, 1e300);
      out.hi.resize(i + 1, -1e300);
      out.band.resize(i + 1, 0);
      out.before.resize(i + 1, 0);
      out.after.resize(i + 1, 0);
    }
    if (!v.extent.empty()) {
      out.lo[i] = std::min(out.lo[i], columns ? v.extent.xmin : v.extent.ymin);
      out.hi[i] = std::max(out.hi[i], columns ? v.extent.xmax : v.extent.ymax);
    }
    if (!columns) out.band[i] = std::max(out.band[i], v.label_band_mm);
    out.before[i] = std::max(out.before[i], columns ? v.dimensions.left : v.dimensions.top);
    out.after[i] = std::max(out.after[i], columns ? v.dimensions.right : v.dimensions.bottom);
  }
  return out;
}

}  // namespace

std::vector<Point2> grid_view_points(const std::vector<GridViewFit>& views, double s, const Rect2& area,
                                     double gap_mm) {
  const GridBands columns = grid_bands(views, true), rows = grid_bands(views, false);
  const auto size = [&](const GridBands& b, std::size_t i) { return std::max(0.0, s * (b.hi[i] - b.lo[i])); };
  const double width =
      s * columns.world() + columns.bands() + gap_mm * static_cast<double>(columns.lo.size() - 1);
  const double height = s * rows.world() + rows.bands() + gap_mm * static_cast<double>(rows.lo.size() - 1);
  // Each column's left edge and each row's top edge, the grid centred in the area.
  std::vector<double> left(columns.lo.size()), top(rows.lo.size());
  double x = area.xmin + 0.5 * (area.width() - width);
  for (std::size_t c = 0; c < left.size(); ++c)
    left[c] = x + columns.before[c], x += columns.before[c] + size(columns, c) + columns.after[c] + gap_mm;
  double y = area.ymin + 0.5 * (area.height() - height);
  for (std::size_t r = 0; r < top.size(); ++r)
    top[r] = y + rows.before[r], y += rows.before[r] + size(rows, r) + rows.after[r] + rows.band[r] + gap_mm;
  std::vector<Point2> out;
  for (const GridViewFit& v : views) {
    const auto c = static_cast<std::size_t>(v.column), r = static_cast<std::size_t>(v.row);
    // Picture x grows to the right on the page, picture y upwards (page y down).
    const double cx = columns.lo[c] <= columns.hi[c] ? left[c] - s * columns.lo[c] : left[c];
    const double cy = rows.lo[r] <= rows.hi[r] ? top[r] + s * rows.hi[r] : top[r];
    out.push_back({cx, cy});
  }
  return out;
}

double fitted_grid_scale(const std::vector<GridViewFit>& views, const Rect2& area, double gap_mm) {
  const GridBands columns = grid_bands(views, true), rows = grid_bands(views, false);
  const double wide = columns.world(), tall = rows.world();
  double best = 1e300;
  if (wide > 0)
    best = std::min(
        best, (area.width() - columns.bands() - gap_mm * static_cast<double>(columns.lo.size() - 1)) / wide);
  if (tall > 0)
    best = std::min(best,
                    (area.height() - rows.bands() - gap_mm * static_cast<double>(rows.lo.size() - 1)) / tall);
  if (!(best > 0) || best >= 1e300) return 1;
  return iso_scale_at_most(best);
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
