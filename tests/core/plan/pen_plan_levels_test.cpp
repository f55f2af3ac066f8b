// Occlusion levels in the pen plan: hidden pieces of different levels are never joined (not even where
// they meet end to end in one pen), and the groups are drawn pen by pen, visible first, then the hidden
// ones by level; cutting hidden strokes into dashes keeps each dash's level.
#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>
#include <vector>

#include "core/plan/hidden_dashes.hpp"
#include "core/plan/pen_plan.hpp"

namespace hlr {
namespace {

PlotPiece piece(Point2 a, Point2 b, int pen, StrokeLayer layer, int level) {
  return {a, b, pen, layer, level};
}

constexpr PenOrder kOrders[] = {PenOrder::None, PenOrder::Greedy, PenOrder::Optimized};
constexpr StrokeLayer V = StrokeLayer::Visible, H = StrokeLayer::Hidden;

// A straight line of pen 1 cut into five pieces whose levels alternate, plus pen 2 pieces given first.
std::vector<PlotPiece> chain() {
  return {piece({0, 50}, {10, 50}, 2, H, 3), piece({0, 40}, {10, 40}, 2, V, 0),
          piece({0, 0}, {10, 0}, 1, H, 1),   piece({10, 0}, {20, 0}, 1, H, 2),
          piece({20, 0}, {30, 0}, 1, H, 1),  piece({30, 0}, {40, 0}, 1, H, 0),
          piece({40, 0}, {50, 0}, 1, V, 0),  piece({0, 20}, {10, 20}, 2, H, 1)};
}

TEST(PenPlanLevels, PiecesOfDifferentLevelsAreNeverJoined) {
  for (PenOrder order : kOrders) {
    PlanOptions o;
    o.order = order;
    const PenPlan plan = plan_pen_strokes(chain(), o);
    // Pen 1: visible [40,50]; plain hidden [30,40]; level 1 [0,10] and [20,30] (apart: two strokes);
    // level 2 [10,20]. Pen 2: visible, level 1, level 3. Joined across levels there would be fewer.
    EXPECT_EQ(plan.stats.lift_lower_bound, 8u) << static_cast<int>(order);
    EXPECT_EQ(plan.strokes.size(), 8u) << static_cast<int>(order);
    for (const PlotStroke& s : plan.strokes) {
      ASSERT_EQ(s.points.size(), 2u);  // each piece alone: none continues into a piece of another level
      EXPECT_NEAR(std::abs(s.points[1].x - s.points[0].x), 10, 1e-9);
      if (s.layer == V) {
        EXPECT_EQ(s.level, 0);
      }
    }
  }
}

TEST(PenPlanLevels, GroupsInPenThenVisibleThenLevelOrder) {
  for (PenOrder order : kOrders) {
    PlanOptions o;
    o.order = order;
    const PenPlan plan = plan_pen_strokes(chain(), o);
    std::vector<std::tuple<int, int, int>> seen;  // pen, hidden, level
    for (const PlotStroke& s : plan.strokes) seen.emplace_back(s.pen, s.layer == H ? 1 : 0, s.level);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end())) << static_cast<int>(order);
    const std::vector<std::tuple<int, int, int>> expected{{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 1, 1},
                                                          {1, 1, 2}, {2, 0, 0}, {2, 1, 1}, {2, 1, 3}};
    EXPECT_EQ(seen, expected) << static_cast<int>(order);
  }
}

TEST(PenPlanLevels, WithoutLevelsTheOrderIsAsBefore) {
  // All hidden pieces at level 0: one hidden group per pen, joined end to end as before.
  std::vector<PlotPiece> pieces{piece({0, 0}, {10, 0}, 1, H, 0), piece({10, 0}, {20, 0}, 1, H, 0),
                                piece({20, 0}, {30, 0}, 1, V, 0)};
  PlanOptions o;
  o.order = PenOrder::Greedy;
  const PenPlan plan = plan_pen_strokes(pieces, o);
  ASSERT_EQ(plan.strokes.size(), 2u);
  EXPECT_EQ(plan.strokes[0].layer, V);
  EXPECT_EQ(plan.strokes[1].layer, H);
  EXPECT_EQ(plan.strokes[1].points.size(), 2u);  // 0 → 20 straight on: one segment
  EXPECT_EQ(plan.strokes[1].level, 0);
}

TEST(PenPlanLevels, DashesKeepTheirStrokesLevel) {
  PlanOptions o;
  o.order = PenOrder::Greedy;
  PenPlan plan = plan_pen_strokes(chain(), o);
  dash_hidden_strokes(plan, DashPattern{1, 1}, o);
  std::size_t by_level[4] = {0, 0, 0, 0};
  for (const PlotStroke& s : plan.strokes)
    if (s.layer == H) ++by_level[s.level];
  // 10 mm hidden strokes, 1 mm dashes and gaps: 5 dashes each (n gaps with n·2 + 1 ≈ 10 → 4.5 → 4 or 5).
  // Pen 1: one plain stroke, two of level 1, one of level 2; pen 2: one of level 1, one of level 3.
  EXPECT_GT(by_level[0], 0u);
  EXPECT_EQ(by_level[1], 3 * by_level[0]);
  EXPECT_EQ(by_level[2], by_level[0]);
  EXPECT_EQ(by_level[3], by_level[0]);
  for (const PlotStroke& s : plan.strokes) {
    if (s.layer == V) {
      EXPECT_EQ(s.level, 0);
    }
  }
}

}  // namespace
}  // namespace hlr
