// Helpers shared by the pen-planner tests: grid segments, unit-edge multisets, travel recomputation.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <vector>

#include "core/plan/grid_point.hpp"
#include "core/plan/pen_plan.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::plan_test {

using Rng = hlr::test::Rng;  // tests/support/seeded_rng.hpp

inline GridPoint to_grid(Point2 p, double grid) { return {std::llround(p.x / grid), std::llround(p.y / grid)}; }

// A primitive lattice step of a grid segment, normalised so that (a, b) and (b, a) compare equal.
using Unit = std::tuple<std::int64_t, std::int64_t, std::int64_t, std::int64_t>;

inline void append_units(GridPoint a, GridPoint b, std::vector<Unit>& out) {
  const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
  const std::int64_t g = std::gcd(std::llabs(dx), std::llabs(dy));
  if (g == 0) return;
  const std::int64_t sx = dx / g, sy = dy / g;
  for (std::int64_t k = 0; k < g; ++k) {
    GridPoint p{a.x + k * sx, a.y + k * sy}, q{p.x + sx, p.y + sy};
    if (std::tie(q.x, q.y) < std::tie(p.x, p.y)) std::swap(p, q);
    out.emplace_back(p.x, p.y, q.x, q.y);
  }
}

// The multiset (sorted) of unit steps the strokes draw.
inline std::vector<Unit> stroke_units(const std::vector<PlotStroke>& strokes, double grid) {
  std::vector<Unit> u;
  for (const PlotStroke& s : strokes)
    for (std::size_t k = 1; k < s.points.size(); ++k) append_units(to_grid(s.points[k - 1], grid), to_grid(s.points[k], grid), u);
  std::sort(u.begin(), u.end());
  return u;
}

// The set (sorted, unique) of unit steps of the snapped pieces.
inline std::vector<Unit> piece_unit_set(const std::vector<PlotPiece>& pieces, double grid) {
  std::vector<Unit> u;
  for (const PlotPiece& p : pieces) append_units(to_grid(p.a, grid), to_grid(p.b, grid), u);
  std::sort(u.begin(), u.end());
  u.erase(std::unique(u.begin(), u.end()), u.end());
  return u;
}

// Pen-up moves recomputed from the strokes: home → first, between strokes, last → home.
inline std::vector<double> pen_up_moves(const std::vector<PlotStroke>& strokes, Point2 home) {
  std::vector<double> m;
  if (strokes.empty()) return m;
  Point2 here = home;
  for (const PlotStroke& s : strokes) {
    m.push_back(std::hypot(s.points.front().x - here.x, s.points.front().y - here.y));
    here = s.points.back();
  }
  m.push_back(std::hypot(home.x - here.x, home.y - here.y));
  return m;
}

inline double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

}  // namespace hlr::plan_test
