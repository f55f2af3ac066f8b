// Dimensions: lines, arrowheads and values where a front view at 1 mm per unit puts them, worked out by hand.
#include "core/device/page/dimension_strokes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/device/page/sheet_layout.hpp"

namespace hlr {
namespace {

// Looking along +y with z up: world (x, ·, z) lands at page (100 + x, 100 − z) (1 mm per unit).
struct Front {
  Camera camera;
  PageLayout layout;
  Front() {
    OrthoParameters o;
    o.eye = {0, -50, 0};
    o.target = {0, 0, 0};
    o.height = 2;  // focal 1: a picture unit is a world unit
    camera = ortho_camera(o);
    layout = view_layout({297, 210}, {100, 100}, 1);
  }
};

bool near(Point2 p, double x, double y) { return std::abs(p.x - x) < 1e-9 && std::abs(p.y - y) < 1e-9; }

TEST(DimensionStrokes, ValuesDropTrailingZeros) {
  EXPECT_EQ(dimension_value_text(80, 2), "80");
  EXPECT_EQ(dimension_value_text(12.5, 2), "12.5");
  EXPECT_EQ(dimension_value_text(3.14159, 2), "3.14");
  EXPECT_EQ(dimension_value_text(3.14159, 0), "3");
  EXPECT_EQ(dimension_value_text(0.0004, 2), "0");
}

TEST(DimensionStrokes, AHorizontalRunOverItsPoints) {
  const Front f;
  PageDimension d;
  d.from = {0, 0, 0};
  d.to = {80, 0, 0};
  d.offset_mm = 10;
  const DimensionDrawing drawing = dimension_strokes(d, f.camera, f.layout);
  ASSERT_TRUE(drawing.problem.empty());
  EXPECT_DOUBLE_EQ(drawing.value, 80);
  EXPECT_EQ(drawing.text, "80");
  // Extension lines from 1.5 mm above each point to 2 mm past the dimension line at y = 90.
  ASSERT_GE(drawing.strokes.size(), 5U);
  EXPECT_TRUE(near(drawing.strokes[0][0], 100, 98.5) && near(drawing.strokes[0][1], 100, 88));
  EXPECT_TRUE(near(drawing.strokes[1][0], 180, 98.5) && near(drawing.strokes[1][1], 180, 88));
  // The dimension line, and arrowheads 3 mm long at 15° pointing at its ends.
  EXPECT_TRUE(near(drawing.strokes[2][0], 100, 90) && near(drawing.strokes[2][1], 180, 90));
  const double c = 3 * std::cos(std::numbers::pi / 12), s = 3 * std::sin(std::numbers::pi / 12);
  EXPECT_TRUE(near(drawing.strokes[3][0], 100 + c, 90 - s) && near(drawing.strokes[3][1], 100, 90) &&
              near(drawing.strokes[3][2], 100 + c, 90 + s));
  EXPECT_TRUE(near(drawing.strokes[4][1], 180, 90));
  // The value's letters lie above the line (y < 90), about its middle.
  for (std::size_t k = 5; k < drawing.strokes.size(); ++k)
    for (const Point2& p : drawing.strokes[k]) {
      EXPECT_LT(p.y, 90);
      EXPECT_NEAR(p.x, 140, 5);
    }
}

TEST(DimensionStrokes, NegativeOffsetsGoBelowAndTheTextTurnsWithTheLine) {
  const Front f;
  PageDimension d;
  d.from = {0, 0, 0};
  d.to = {0, 0, 30};
  d.offset_mm = 12;
  d.direction = DimensionDirection::Vertical;
  const DimensionDrawing drawing = dimension_strokes(d, f.camera, f.layout);
  EXPECT_DOUBLE_EQ(drawing.value, 30);
  // Upright: read from the bottom up, offsets to the left: the line at x = 100 − 12 from y 100 to 70.
  EXPECT_TRUE(near(drawing.strokes[2][0], 88, 100) && near(drawing.strokes[2][1], 88, 70));
  for (std::size_t k = 5; k < drawing.strokes.size(); ++k)
    for (const Point2& p : drawing.strokes[k]) EXPECT_LT(p.x, 88);  // left of the line
  d.offset_mm = -12;
  const DimensionDrawing right = dimension_strokes(d, f.camera, f.layout);
  EXPECT_TRUE(near(right.strokes[2][0], 112, 100) && near(right.strokes[2][1], 112, 70));
  for (std::size_t k = 5; k < right.strokes.size(); ++k)
    for (const Point2& p : right.strokes[k]) EXPECT_GT(p.x, 112);
}

TEST(DimensionStrokes, AlignedMeasuresTheTrueDistanceHorizontalTheViewsRight) {
  const Front f;
  PageDimension d;
  d.from = {0, 0, 0};
  d.to = {30, 40, 0};  // 40 units deeper: 50 apart, 30 across
  EXPECT_DOUBLE_EQ(dimension_strokes(d, f.camera, f.layout).value, 50);
  d.direction = DimensionDirection::Horizontal;
  EXPECT_DOUBLE_EQ(dimension_strokes(d, f.camera, f.layout).value, 30);
  d.text = "R30";
  EXPECT_EQ(dimension_strokes(d, f.camera, f.layout).text, "R30");
}

TEST(DimensionStrokes, PointsThatFallTogetherOrBehindTheEyeAreNotDrawn) {
  const Front f;
  PageDimension d;
  d.from = {5, 0, 0};
  d.to = {5, 20, 0};  // one behind the other
  const DimensionDrawing together = dimension_strokes(d, f.camera, f.layout);
  EXPECT_FALSE(together.problem.empty());
  EXPECT_TRUE(together.strokes.empty());
  LookatParameters l;
  l.eye = {0, -10, 0};
  l.target = {0, 0, 0};
  d.to = {5, -20, 0};
  EXPECT_FALSE(dimension_strokes(d, lookat_camera(l), f.layout).problem.empty());
}

}  // namespace
}  // namespace hlr
