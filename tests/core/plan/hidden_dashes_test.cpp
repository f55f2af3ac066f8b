// dash_hidden_strokes(): hidden strokes cut into pen-down dashes that start and end each stroke, the
// pattern running on round corners, visible strokes untouched, and the figures of what is drawn.
#include "core/plan/hidden_dashes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace hlr {
namespace {

double length_of(const PlotStroke& s) {
  double l = 0;
  for (std::size_t k = 1; k < s.points.size(); ++k) l += distance(s.points[k - 1], s.points[k]);
  return l;
}

PlotStroke stroke(std::vector<Point2> points, StrokeLayer layer, int pen = 1) {
  PlotStroke s;
  s.points = std::move(points);
  s.layer = layer;
  s.pen = pen;
  return s;
}

PlanOptions grid_options() {
  PlanOptions o;
  o.grid_mm = 0.025;
  o.home = {0, 0};
  return o;
}

// 35.5 mm with 2 mm dashes and 1.5 mm gaps: (35.5 − 2) / 3.5 = 9.57, so 10 gaps and 11 dashes, the
// pattern stretched by 35.5 / (10 · 3.5 + 2) = 0.9595: dashes of 1.919 mm every 3.358 mm, the first
// from 0, the last to 35.5.
TEST(HiddenDashes, AStraightStrokeStartsAndEndsWithADash) {
  PenPlan plan;
  plan.strokes.push_back(stroke({{10, 20}, {45.5, 20}}, StrokeLayer::Hidden, 2));
  dash_hidden_strokes(plan, {2, 1.5}, grid_options());
  ASSERT_EQ(plan.strokes.size(), 11U);
  const double stretch = 35.5 / 37, dash = 2 * stretch, step = 3.5 * stretch;
  for (std::size_t k = 0; k < plan.strokes.size(); ++k) {
    SCOPED_TRACE(k);
    const PlotStroke& s = plan.strokes[k];
    EXPECT_EQ(s.pen, 2);
    EXPECT_EQ(s.layer, StrokeLayer::Hidden);
    ASSERT_EQ(s.points.size(), 2U);
    EXPECT_NEAR(s.points[0].x, 10 + step * static_cast<double>(k), 0.0125 + 1e-9);
    EXPECT_NEAR(s.points[1].x, 10 + step * static_cast<double>(k) + dash, 0.0125 + 1e-9);
    EXPECT_EQ(s.points[0].y, 20);
  }
  EXPECT_EQ(plan.strokes.front().points.front().x, 10);
  EXPECT_EQ(plan.strokes.back().points.back().x, 45.5);
  EXPECT_EQ(plan.stats.hidden_dashes, 11U);
  EXPECT_EQ(plan.stats.lifts, 11U);
  EXPECT_NEAR(plan.stats.pen_down_mm, 11 * dash, 11 * 0.025);
  // Pen-up: home to the first dash, ten gaps, back home from the stroke's end.
  EXPECT_NEAR(plan.stats.pen_up_mm, std::hypot(10, 20) + 10 * (step - dash) + std::hypot(45.5, 20),
              10 * 0.025);
}

// The pattern runs on round a corner: the dash that reaches it turns with the stroke, and the dashes'
// pen-down lengths add up to what the pattern gives for the whole length.
TEST(HiddenDashes, ThePatternRunsRoundCorners) {
  PenPlan plan;
  plan.strokes.push_back(stroke({{0, 0}, {8, 0}, {8, 12}}, StrokeLayer::Hidden));
  dash_hidden_strokes(plan, {2, 1.5}, grid_options());
  // 20 mm: round(18 / 3.5) = 5 gaps, 6 dashes, stretch 20 / 19.5; the third dash covers arc length
  // [7, 9] · 20/19.5 = [7.18, 9.23], which holds the corner at 8.
  ASSERT_EQ(plan.strokes.size(), 6U);
  double down = 0;
  int turning = 0;
  for (const PlotStroke& s : plan.strokes) {
    down += length_of(s);
    turning += s.points.size() == 3;
  }
  EXPECT_NEAR(down, 6 * 2 * 20 / 19.5, 6 * 0.05);
  EXPECT_EQ(turning, 1);
  ASSERT_EQ(plan.strokes[2].points.size(), 3U);
  EXPECT_EQ(plan.strokes[2].points[1], (Point2{8, 0}));
}

// A stroke shorter than a dash and a half-period stays one dash; visible strokes are never cut; the
// order of the plan is kept.
TEST(HiddenDashes, ShortStrokesAndVisibleStrokesStayWhole) {
  PenPlan plan;
  plan.strokes.push_back(stroke({{0, 0}, {50, 0}}, StrokeLayer::Visible));
  plan.strokes.push_back(stroke({{50, 0}, {50, 3}}, StrokeLayer::Hidden));
  plan.strokes.push_back(stroke({{0, 5}, {50, 5}}, StrokeLayer::Visible, 3));
  dash_hidden_strokes(plan, {2, 1.5}, grid_options());
  ASSERT_EQ(plan.strokes.size(), 3U);
  EXPECT_EQ(plan.strokes[0].layer, StrokeLayer::Visible);
  EXPECT_EQ(plan.strokes[1].points, (std::vector<Point2>{{50, 0}, {50, 3}}));
  EXPECT_EQ(plan.strokes[2].pen, 3);
  EXPECT_EQ(plan.stats.hidden_dashes, 1U);
  EXPECT_NEAR(plan.stats.pen_down_mm, 103, 1e-9);
}

TEST(HiddenDashes, ABadPatternIsRefused) {
  PenPlan plan;
  EXPECT_THROW(dash_hidden_strokes(plan, {0, 1.5}, grid_options()), std::invalid_argument);
  EXPECT_THROW(dash_hidden_strokes(plan, {2, NAN}, grid_options()), std::invalid_argument);
}

}  // namespace
}  // namespace hlr
