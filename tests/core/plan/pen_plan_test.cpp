// plan_pen_strokes(): the thesis's small drawings, the three orders, grouping by pen and layer, the
// statistics, and the optimum on small instances checked by brute force.
#include "core/plan/pen_plan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "tests/core/plan/plan_test_util.hpp"

namespace hlr {
namespace {

using plan_test::Rng;

PlanOptions options(PenOrder order, double grid = 0.025, Point2 home = {0, 0}) {
  PlanOptions o;
  o.order = order;
  o.grid_mm = grid;
  o.home = home;
  return o;
}

constexpr PenOrder kOrders[] = {PenOrder::None, PenOrder::Greedy, PenOrder::Optimized};

void expect_stats_consistent(const PenPlan& plan, const PlanOptions& o) {
  const PlanStats& st = plan.stats;
  EXPECT_EQ(st.lifts, plan.strokes.size());
  const std::vector<double> moves = plan_test::pen_up_moves(plan.strokes, o.home);
  EXPECT_NEAR(st.pen_up_mm, plan_test::sum(moves), 1e-6);
  if (moves.empty()) {
    EXPECT_EQ(st.pen_up_mean_mm, 0);
    EXPECT_EQ(st.pen_up_median_mm, 0);
  } else {
    EXPECT_NEAR(st.pen_up_mean_mm, plan_test::sum(moves) / static_cast<double>(moves.size()), 1e-9);
    std::vector<double> sorted = moves;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t h = sorted.size() / 2;
    EXPECT_NEAR(st.pen_up_median_mm, sorted.size() % 2 ? sorted[h] : 0.5 * (sorted[h - 1] + sorted[h]), 1e-9);
  }
  double down = 0;
  for (const PlotStroke& s : plan.strokes) {
    EXPECT_GE(s.points.size(), 2u);
    for (std::size_t k = 1; k < s.points.size(); ++k) {
      EXPECT_FALSE(s.points[k].x == s.points[k - 1].x && s.points[k].y == s.points[k - 1].y);
      down += std::hypot(s.points[k].x - s.points[k - 1].x, s.points[k].y - s.points[k - 1].y);
    }
  }
  EXPECT_NEAR(st.pen_down_mm, down, 1e-6);
  EXPECT_NEAR(st.plot_seconds,
              st.pen_down_mm / o.speeds.pen_down_mm_per_s + st.pen_up_mm / o.speeds.pen_up_mm_per_s +
                  static_cast<double>(st.lifts) * o.speeds.lift_s,
              1e-9);
  EXPECT_GE(st.planning_ms, 0);
  if (o.order != PenOrder::None) {
    EXPECT_EQ(st.lifts, st.lift_lower_bound);
  }
  EXPECT_GE(st.lifts, st.lift_lower_bound);
}

PlotPiece piece(Point2 a, Point2 b, int pen = 1, StrokeLayer layer = StrokeLayer::Visible) {
  return {a, b, pen, layer};
}

TEST(PenPlan, EmptyAndInvalid) {
  for (PenOrder order : kOrders) {
    const PenPlan p = plan_pen_strokes({}, options(order));
    EXPECT_TRUE(p.strokes.empty());
    EXPECT_EQ(p.stats.pen_up_mm, 0);
    EXPECT_EQ(p.stats.lifts, 0u);
    EXPECT_EQ(p.stats.lift_lower_bound, 0u);
  }
  PlanOptions bad;
  bad.grid_mm = 0;
  EXPECT_THROW(plan_pen_strokes({}, bad), std::invalid_argument);
  bad.grid_mm = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(plan_pen_strokes({}, bad), std::invalid_argument);
  // Degenerate and non-finite pieces are dropped and counted.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PenPlan p =
      plan_pen_strokes({piece({1, 1}, {1.001, 1}), piece({nan, 0}, {1, 1}), piece({0, 0}, {5, 0})},
                       options(PenOrder::Optimized));
  EXPECT_EQ(p.stats.pieces, 3u);
  EXPECT_EQ(p.stats.dropped_pieces, 2u);
  ASSERT_EQ(p.strokes.size(), 1u);
}

// A single piece: pen-up to it and back (either way round costs the same when the tour returns home).
TEST(PenPlan, SinglePiece) {
  for (PenOrder order : {PenOrder::Greedy, PenOrder::Optimized}) {
    const PlanOptions o = options(order, 0.025, {0, 0});
    const PenPlan p = plan_pen_strokes({piece({100, 0}, {10, 0})}, o);
    ASSERT_EQ(p.strokes.size(), 1u);
    if (order == PenOrder::Greedy) {
      EXPECT_DOUBLE_EQ(p.strokes[0].points.front().x, 10);  // nearer end first
    }
    EXPECT_NEAR(p.stats.pen_up_mm, 110, 1e-9);
    EXPECT_NEAR(p.stats.pen_down_mm, 90, 1e-9);
    EXPECT_NEAR(p.stats.pen_up_median_mm, 55, 1e-9);
    expect_stats_consistent(p, o);
  }
}

std::vector<Point2> hexagon(double side, Point2 c) {
  std::vector<Point2> p(7);
  for (int i = 1; i <= 6; ++i) {
    const double a = (i - 1) * std::numbers::pi / 3;
    p[i] = {c.x + side * std::cos(a), c.y + side * std::sin(a)};
  }
  return p;
}

// Diagram 1.1: hexagon 1…6 with chords 1-3 and 4-6, odd points 1, 3, 4, 6. Starting and finishing at
// point 1 (the thesis's closed tour), the best pen-up lines are 6-1 and 3-4: two sides.
TEST(PenPlan, ThesisSixPointDrawing) {
  const double side = 40;
  const std::vector<Point2> p = hexagon(side, {100, 100});
  std::vector<PlotPiece> pieces;
  for (auto [a, b] : {std::pair{1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 1}, {1, 3}, {4, 6}})
    pieces.push_back(piece(p[a], p[b]));
  for (PenOrder order : kOrders) {
    const PlanOptions o = options(order, 0.025, p[1]);
    const PenPlan plan = plan_pen_strokes(pieces, o);
    EXPECT_EQ(plan.stats.merged_pieces, 8u);
    EXPECT_EQ(plan.stats.odd_vertices, 4u);
    EXPECT_EQ(plan.stats.lift_lower_bound, 2u);
    expect_stats_consistent(plan, o);
    if (order == PenOrder::Optimized) {
      EXPECT_EQ(plan.stats.lifts, 2u);
      EXPECT_NEAR(plan.stats.pen_up_mm, 2 * side, 0.05);  // grid rounding of the corners
    }
  }
}

// The wire-frame cube: all eight vertices odd (degree 3), so four strokes — the thesis's four pen-up lines
// of a closed tour; 105 possible pairings.
TEST(PenPlan, ThesisWireFrameCube) {
  std::vector<Point2> v;
  const double az = 0.5, el = 0.35;
  for (int i = 0; i < 8; ++i) {
    const double x = i & 1 ? 1 : -1, y = i & 2 ? 1 : -1, z = i & 4 ? 1 : -1;
    const double xr = x * std::cos(az) - y * std::sin(az), yr = x * std::sin(az) + y * std::cos(az);
    v.push_back({100 + 40 * xr, 100 + 40 * (z * std::cos(el) - yr * std::sin(el))});
  }
  std::vector<PlotPiece> pieces;
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) pieces.push_back(piece(v[i], v[i | bit]));
  ASSERT_EQ(pieces.size(), 12u);
  for (PenOrder order : kOrders) {
    const PlanOptions o = options(order, 0.025, {0, 0});
    const PenPlan plan = plan_pen_strokes(pieces, o);
    EXPECT_EQ(plan.stats.merged_pieces, 12u);
    EXPECT_EQ(plan.stats.odd_vertices, 8u);
    EXPECT_EQ(plan.stats.lift_lower_bound, 4u);
    expect_stats_consistent(plan, o);
    if (order != PenOrder::None) {
      EXPECT_EQ(plan.stats.lifts, 4u);
    }
  }
}

// The cube in general view, visible edges only (Diagram 3.2): silhouette 1…6 and the inner vertex 8 joined
// to 2, 4, 6 — nine edges, odd points {2, 4, 6, 8}, two strokes (the closed tour's two pen-up lines).
TEST(PenPlan, ThesisCubeVisibleEdges) {
  const std::vector<Point2> h = hexagon(30, {150, 100});
  const Point2 eight{152, 98};
  std::vector<PlotPiece> pieces;
  for (int i = 1; i <= 6; ++i) pieces.push_back(piece(h[i], h[i % 6 + 1]));
  for (int i : {2, 4, 6}) pieces.push_back(piece(eight, h[i]));
  for (PenOrder order : kOrders) {
    const PlanOptions o = options(order, 0.025, {0, 0});
    const PenPlan plan = plan_pen_strokes(pieces, o);
    EXPECT_EQ(plan.stats.merged_pieces, 9u);
    EXPECT_EQ(plan.stats.odd_vertices, 4u);
    EXPECT_EQ(plan.stats.lift_lower_bound, 2u);
    expect_stats_consistent(plan, o);
  }
}

// None: the snapped pieces exactly as given, in file order per pen and layer, a piece continuing the
// previous stroke only when it starts where that ended.
TEST(PenPlan, NonePreservesPieces) {
  Rng r(5);
  std::vector<PlotPiece> pieces;
  Point2 last{10, 10};
  for (int i = 0; i < 300; ++i) {
    const Point2 a = r.integer(0, 2) ? last : Point2{r(0, 200), r(0, 200)};
    const Point2 b{r(0, 200), r(0, 200)};
    // Drawn one statement at a time: the order a function's arguments are evaluated in differs between
    // compilers, and the pieces must not (the layer first, as GCC has always drawn them).
    const StrokeLayer layer = r.integer(0, 3) ? StrokeLayer::Visible : StrokeLayer::Hidden;
    const int pen = r.integer(1, 3);
    pieces.push_back(piece(a, b, pen, layer));
    last = b;
  }
  pieces.push_back(piece({5, 5}, {5.001, 5.001}));  // snaps to nothing
  const double grid = 0.025;
  const PlanOptions o = options(PenOrder::None, grid);
  const PenPlan plan = plan_pen_strokes(pieces, o);
  expect_stats_consistent(plan, o);
  EXPECT_EQ(plan.stats.dropped_pieces, 1u);
  // Expected: per (pen, layer) in increasing pen, visible first, the snapped pieces in file order.
  std::vector<std::pair<GridPoint, GridPoint>> want, got;
  for (int pen = 1; pen <= 3; ++pen)
    for (StrokeLayer layer : {StrokeLayer::Visible, StrokeLayer::Hidden})
      for (const PlotPiece& p : pieces)
        if (p.pen == pen && p.layer == layer) {
          const GridPoint a = plan_test::to_grid(p.a, grid), b = plan_test::to_grid(p.b, grid);
          if (!(a == b)) want.emplace_back(a, b);
        }
  std::size_t joins = 0;
  for (const PlotStroke& s : plan.strokes) {
    for (std::size_t k = 1; k < s.points.size(); ++k)
      got.emplace_back(plan_test::to_grid(s.points[k - 1], grid), plan_test::to_grid(s.points[k], grid));
    joins += s.points.size() - 2;
  }
  EXPECT_EQ(got, want);
  EXPECT_GT(joins, 50u);  // a third of the pieces continue the previous one
}

// Pens one after another in increasing number, visible before hidden; never joined across pen or layer.
TEST(PenPlan, GroupsByPenAndLayer) {
  std::vector<PlotPiece> pieces{piece({0, 0}, {10, 0}, 3), piece({10, 0}, {20, 0}, 1, StrokeLayer::Hidden),
                                piece({20, 0}, {30, 0}, 1), piece({30, 0}, {40, 0}, 2),
                                piece({40, 0}, {50, 0}, 1)};
  for (PenOrder order : kOrders) {
    const PlanOptions o = options(order);
    const PenPlan plan = plan_pen_strokes(pieces, o);
    expect_stats_consistent(plan, o);
    std::vector<std::pair<int, StrokeLayer>> seen;
    for (const PlotStroke& s : plan.strokes) seen.emplace_back(s.pen, s.layer);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end(), [](auto a, auto b) {
      return a.first != b.first ? a.first < b.first
                                : (a.second == StrokeLayer::Visible && b.second == StrokeLayer::Hidden);
    }));
    // Pen 1 visible holds [20,30] and [40,50] (two components); pen 1 hidden, pens 2 and 3 one each.
    EXPECT_EQ(plan.stats.lift_lower_bound, 5u);
    if (order != PenOrder::None) {
      EXPECT_EQ(plan.stats.lifts, 5u);
    }
  }
}

}  // namespace
}  // namespace hlr
