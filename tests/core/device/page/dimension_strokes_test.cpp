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

TEST(DimensionStrokes, DistancesInOtherUnitsAreConvertedAndMarked) {
  EXPECT_EQ(dimension_distance_text(80, DimensionUnit::Mm, 2), "80");
  EXPECT_EQ(dimension_distance_text(80, DimensionUnit::Cm, 2), "8 cm");
  EXPECT_EQ(dimension_distance_text(1250, DimensionUnit::M, 2), "1.25 m");
  EXPECT_EQ(dimension_distance_text(25.4 * 3.5, DimensionUnit::In, 3), "3.5\"");
  EXPECT_EQ(dimension_unit_named("in"), DimensionUnit::In);
  EXPECT_FALSE(dimension_unit_named("ft").has_value());
  const Front f;
  PageDimension d;
  d.from = {0, 0, 0};
  d.to = {50.8, 0, 0};
  d.unit = DimensionUnit::In;
  EXPECT_EQ(dimension_strokes(d, f.camera, f.layout).text, "2\"");
}

// The angle at world (10, 0, 0) between legs along +x and +z: page vertex (110, 100), legs to the right
// (+x) and up the page (−y), a quarter circle of radius 15 between them.
PageDimension right_angle() {
  PageDimension d;
  d.vertex = Point3{10, 0, 0};
  d.from = {40, 0, 0};
  d.to = {10, 0, 40};
  d.radius_mm = 15;
  return d;
}

TEST(DimensionStrokes, ARightAngleIsAQuarterArcBetweenItsLegs) {
  const Front f;
  PageDimension d = right_angle();
  const DimensionDrawing drawing = dimension_strokes(d, f.camera, f.layout);
  ASSERT_TRUE(drawing.problem.empty()) << drawing.problem;
  EXPECT_NEAR(drawing.value, 90, 1e-12);
  EXPECT_EQ(drawing.text, "90\u00b0");
  // Legs 30 and 40 mm long reach past the arc: no extension lines; the arc comes first.
  ASSERT_GE(drawing.strokes.size(), 3U);
  const std::vector<Point2>& arc = drawing.strokes[0];
  EXPECT_TRUE(near(arc.front(), 125, 100));
  EXPECT_TRUE(near(arc.back(), 110, 85));
  for (const Point2& p : arc) {
    EXPECT_NEAR(distance(p, Point2{110, 100}), 15, 1e-9);
    EXPECT_TRUE(p.x >= 110 - 1e-9 && p.y <= 100 + 1e-9);  // within the quarter between the legs
  }
  // Chords leave the circle by at most 0.01 mm: sagitta r(1 − cos(θ/2)).
  for (std::size_t i = 1; i < arc.size(); ++i) {
    const double half = std::asin(distance(arc[i - 1], arc[i]) / 2 / 15);
    EXPECT_LE(15 * (1 - std::cos(half)), 0.01 + 1e-12);
  }
  // Arrowheads at the arc's ends, their wings 3 mm back along the arc (into the quarter).
  const std::vector<Point2>& head_a = drawing.strokes[1];
  ASSERT_EQ(head_a.size(), 3U);
  EXPECT_TRUE(near(head_a[1], 125, 100));
  for (const Point2& wing : {head_a[0], head_a[2]}) {
    EXPECT_NEAR(distance(wing, head_a[1]), 3, 1e-9);
    EXPECT_LT(wing.y, 100);  // back up the arc, away from the leg
  }
  const std::vector<Point2>& head_b = drawing.strokes[2];
  EXPECT_TRUE(near(head_b[1], 110, 85));
  for (const Point2& wing : {head_b[0], head_b[2]}) EXPECT_GT(wing.x, 110);
  // The value outside the arc's middle, beyond 15 mm from the vertex along the bisector.
  for (std::size_t i = 3; i < drawing.strokes.size(); ++i)
    for (const Point2& p : drawing.strokes[i]) {
      EXPECT_GT(distance(p, Point2{110, 100}), 15.5);
      EXPECT_GT(p.x, 110);
      EXPECT_LT(p.y, 100);
    }
}

TEST(DimensionStrokes, AnAngleMeasuresInSpaceAndExtendsShortLegs) {
  const Front f;
  PageDimension d;
  d.vertex = Point3{0, 0, 0};
  d.from = {5, 0, 0};   // 5 mm on the page: shorter than the arc
  d.to = {0, 5, 5};     // up the page, and 5 deeper: 45° to the page, 90° in space
  d.radius_mm = 20;
  const DimensionDrawing drawing = dimension_strokes(d, f.camera, f.layout);
  ASSERT_TRUE(drawing.problem.empty()) << drawing.problem;
  EXPECT_NEAR(drawing.value, 90, 1e-12);
  // Each leg drawn on from 1.5 mm past its point to 2 mm past the arc.
  ASSERT_GE(drawing.strokes.size(), 2U);
  EXPECT_TRUE(near(drawing.strokes[0][0], 106.5, 100) && near(drawing.strokes[0][1], 122, 100));
  EXPECT_TRUE(near(drawing.strokes[1][0], 100, 93.5) && near(drawing.strokes[1][1], 100, 78));
  d.from = {10, 0, 10};
  d.to = {-10, 0, 10};  // 90° again, now the arc runs over the top
  d.text = "A";
  const DimensionDrawing over = dimension_strokes(d, f.camera, f.layout);
  EXPECT_NEAR(over.value, 90, 1e-12);
  EXPECT_EQ(over.text, "A");
}

TEST(DimensionStrokes, ALegThatIsNoEdgeIsDrawnFromTheVertex) {
  const Front f;
  PageDimension d = right_angle();
  d.extend_from = true;  // the leg along +x: from the vertex (110, 100) to 2 mm past the arc
  const DimensionDrawing drawing = dimension_strokes(d, f.camera, f.layout);
  ASSERT_GE(drawing.strokes.size(), 1U);
  EXPECT_TRUE(near(drawing.strokes[0][0], 110, 100) && near(drawing.strokes[0][1], 127, 100));
  EXPECT_NEAR(distance(drawing.strokes[1].front(), Point2{110, 100}), 15, 1e-9);  // then the arc
}

TEST(DimensionStrokes, AnglesWithoutLegsOrOnOneLineAreNotDrawn) {
  const Front f;
  PageDimension d;
  d.vertex = Point3{0, 0, 0};
  d.from = {0, 0, 0};
  d.to = {10, 0, 0};
  EXPECT_FALSE(dimension_strokes(d, f.camera, f.layout).problem.empty());  // a leg of no length
  d.from = {0, 10, 0};  // straight behind the vertex: no length on the page
  EXPECT_FALSE(dimension_strokes(d, f.camera, f.layout).problem.empty());
  d.from = {20, 5, 0};  // along the same page line as the other leg
  const DimensionDrawing flat = dimension_strokes(d, f.camera, f.layout);
  EXPECT_FALSE(flat.problem.empty());
  EXPECT_TRUE(flat.strokes.empty());
}

}  // namespace
}  // namespace hlr
