#include "core/plan/hidden_dashes.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace hlr {
namespace {

double stroke_length(const PlotStroke& s) {
  double length = 0;
  for (std::size_t k = 1; k < s.points.size(); ++k) length += distance(s.points[k - 1], s.points[k]);
  return length;
}

Point2 snapped(Point2 p, double grid) {
  return {std::round(p.x / grid) * grid, std::round(p.y / grid) * grid};
}

// The dashes of one stroke, appended to `out`: dash k covers arc length [k·period, k·period + dash].
void cut_into_dashes(const PlotStroke& stroke, const DashPattern& pattern, double grid,
                     std::vector<PlotStroke>& out) {
  const double length = stroke_length(stroke);
  const double period = pattern.dash_mm + pattern.gap_mm;
  // n gaps: length = n·period + dash after stretching by `stretch`; none when it is too short for one.
  const double gaps = std::round((length - pattern.dash_mm) / period);
  if (!(gaps >= 1)) {
    out.push_back(stroke);
    return;
  }
  const double stretch = length / (gaps * period + pattern.dash_mm);
  const double dash = pattern.dash_mm * stretch, step = period * stretch;
  PlotStroke current;
  current.pen = stroke.pen;
  current.layer = stroke.layer;
  current.level = stroke.level;
  const auto add_point = [&](Point2 p) {
    const Point2 q = snapped(p, grid);
    if (current.points.empty() || !(current.points.back() == q)) current.points.push_back(q);
  };
  const auto close_dash = [&] {
    if (current.points.size() >= 2) out.push_back(current);
    current.points.clear();
  };
  // Walk the polyline once, with the pattern's next boundary in arc length.
  double at = 0;  // arc length at points[k - 1]
  bool down = true;
  double next = dash;  // where the pen next lifts (down) or lowers (up)
  add_point(stroke.points.front());
  for (std::size_t k = 1; k < stroke.points.size(); ++k) {
    const Point2 a = stroke.points[k - 1], b = stroke.points[k];
    const double piece = distance(a, b);
    while (next < at + piece && next < length) {
      const double t = (next - at) / piece;
      const Point2 p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
      if (down) {
        add_point(p);
        close_dash();
        next += step - dash;
      } else {
        add_point(p);
        next += dash;
      }
      down = !down;
    }
    if (down) add_point(b);
    at += piece;
  }
  if (down) close_dash();
}

}  // namespace

void check_dash_pattern(const DashPattern& pattern) {
  if (!(std::isfinite(pattern.dash_mm) && pattern.dash_mm > 0 && std::isfinite(pattern.gap_mm) &&
        pattern.gap_mm > 0))
    throw std::invalid_argument("dash_hidden_strokes: dash and gap must be finite and positive");
}

void dash_hidden_strokes(PenPlan& plan, const DashPattern& pattern, const PlanOptions& options) {
  check_dash_pattern(pattern);
  std::vector<PlotStroke> strokes;
  strokes.reserve(plan.strokes.size());
  std::size_t dashes = 0;
  for (PlotStroke& stroke : plan.strokes) {
    if (stroke.layer != StrokeLayer::Hidden) {
      strokes.push_back(std::move(stroke));
      continue;
    }
    const std::size_t before = strokes.size();
    cut_into_dashes(stroke, pattern, options.grid_mm, strokes);
    dashes += strokes.size() - before;
  }
  plan.strokes = std::move(strokes);
  plan.stats.hidden_dashes = dashes;
  fill_travel_stats(plan.strokes, options, plan.stats);
}

}  // namespace hlr
