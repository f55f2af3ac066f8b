// Sheets of views: ISO scales, ratios, the fitted scale and each view's layout, worked out by hand.
#include "core/device/page/sheet_layout.hpp"

#include <gtest/gtest.h>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"

namespace hlr {
namespace {

TEST(SheetLayout, IsoScalesAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(iso_scale_at_most(1), 1);
  EXPECT_DOUBLE_EQ(iso_scale_at_most(0.37), 0.2);
  EXPECT_DOUBLE_EQ(iso_scale_at_most(0.5), 0.5);
  EXPECT_DOUBLE_EQ(iso_scale_at_most(0.99), 0.5);
  EXPECT_DOUBLE_EQ(iso_scale_at_most(7.9), 5);
  EXPECT_DOUBLE_EQ(iso_scale_at_most(20), 20);
  EXPECT_DOUBLE_EQ(iso_scale_at_most(0.0042), 0.002);
}

TEST(SheetLayout, RatiosReadOneUnitAsAMillimetre) {
  EXPECT_EQ(scale_ratio_text(1), "1:1");
  EXPECT_EQ(scale_ratio_text(0.5), "1:2");
  EXPECT_EQ(scale_ratio_text(0.02), "1:50");
  EXPECT_EQ(scale_ratio_text(5), "5:1");
  EXPECT_EQ(scale_ratio_text(0.4), "1:2.5");
}

TEST(SheetLayout, TheFittedScaleIsTheLargestIsoScaleAtWhichEveryViewStaysInside) {
  const PageSpec spec{{297, 210}, 10};
  // A view at (100, 60) reaching 30 units right, 10 left, 5 up and 20 down, label band 8 mm:
  //   right  (287 − 100) / 30 = 6.23   left (100 − 10) / 10 = 9
  //   up     (60 − 10) / 5 = 10        down (200 − 60 − 8) / 20 = 6.6
  // Largest ISO scale ≤ 6.23: 5.
  const SheetViewFit a{{100, 60}, std::nullopt, Rect2{-10, -20, 30, 5}, 8, {}};
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a}, spec), 5);
  // The paper's scale wins.
  PageSpec scaled = spec;
  scaled.mm_per_unit = 0.25;
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a}, scaled), 0.25);
  // Nothing to fit: 1.
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({}, spec), 1);
  // A point outside the margins constrains nothing.
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({{{5, 60}, std::nullopt, Rect2{-1, -1, 1, 1}, 0, {}}}, spec), 1);
}

TEST(SheetLayout, FittedViewsKeepClearOfOneAnotherAndOfTheTitleBlock) {
  const PageSpec spec{{297, 210}, 10};
  // Two views 100 mm apart along x, each reaching 10 units towards the other: side by side with the 5 mm
  // gap, 20·s + 5 ≤ 100, s ≤ 4.75 (apart along y they cannot be: they share a row). ISO: 2.
  const SheetViewFit a{{100, 100}, std::nullopt, Rect2{-10, -5, 10, 5}, 0, {}};
  const SheetViewFit b{{200, 100}, std::nullopt, Rect2{-10, -5, 10, 5}, 0, {}};
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a, b}, spec), 2);
  // b at a scale of its own, 3 mm per unit: 10·s + 30 + 5 ≤ 100, s ≤ 6.5; a's margins: (100 − 10)/10 = 9,
  // (100 − 10)/5 = 18. ISO: 5.
  SheetViewFit fixed = b;
  fixed.mm_per_unit = 3;
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a, fixed}, spec), 5);
  // Diagonal neighbours may be apart along either axis; the freer one counts. c at (200, 180), 80 mm
  // below on a taller sheet: along y 10·s + 5 ≤ 80 (s ≤ 7.5) beats along x (s ≤ 4.75); a's own margins
  // allow 9, c's (287 − 200)/10 = 8.7. ISO: 5.
  const SheetViewFit c{{200, 180}, std::nullopt, Rect2{-10, -5, 10, 5}, 0, {}};
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a, c}, PageSpec{{297, 300}, 10}), 5);
  // The title block at x ≥ 150, y ≥ 150: a view at (100, 100) reaching 10 units right and 5 down stays to
  // its left (10·s + 5 ≤ 50, s ≤ 4.5) or above it (5·s + 5 ≤ 50, s ≤ 9): 9 → its margins' 9 → ISO 5.
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a}, spec, Rect2{150, 150, 287, 200}), 5);
  // Reaching 20 units right and 10 down: left 45/20 = 2.25, above 45/10 = 4.5 → ISO 2.
  const SheetViewFit wide{{100, 100}, std::nullopt, Rect2{-5, -10, 20, 5}, 0, {}};
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({wide}, spec, Rect2{150, 150, 287, 200}), 2);
}

TEST(SheetLayout, TheFitKeepsRoomForTheDimensions) {
  const PageSpec spec{{297, 210}, 10};
  // The view of the first test (ISO 5 without dimensions), its dimensions reaching 40 mm right of the
  // drawing: (287 − 100 − 40) / 30 = 4.9 → ISO 2. Reaching 40 mm below instead: (200 − 60 − 8 − 40) / 20 =
  // 4.6 → 2 as well; 10 mm below: (200 − 60 − 8 − 10) / 20 = 6.1, and the right's 6.23: ISO 5.
  SheetViewFit a{{100, 60}, std::nullopt, Rect2{-10, -20, 30, 5}, 8, {}};
  a.dimensions.right = 40;
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a}, spec), 2);
  a.dimensions = {0, 0, 0, 40};
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a}, spec), 2);
  a.dimensions = {0, 0, 0, 10};
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a}, spec), 5);
  // Two views side by side 100 mm apart (ISO 2 without dimensions: 20·s + 5 ≤ 100): a's dimensions 30 mm
  // to its right leave 20·s + 35 ≤ 100, s ≤ 3.25: still 2; 60 mm: s ≤ 1.75 → 1.
  SheetViewFit b{{100, 100}, std::nullopt, Rect2{-10, -5, 10, 5}, 0, {}};
  const SheetViewFit c{{200, 100}, std::nullopt, Rect2{-10, -5, 10, 5}, 0, {}};
  b.dimensions.right = 30;
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({b, c}, spec), 2);
  b.dimensions.right = 60;
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({b, c}, spec), 1);
}

TEST(SheetLayout, AViewPutsItsPictureOriginAtItsPoint) {
  const PageLayout layout = view_layout({420, 297}, {100, 80}, 4);
  const Point2 origin = layout.to_page_mm({0, 0});
  EXPECT_NEAR(origin.x, 100, 1e-12);
  EXPECT_NEAR(origin.y, 80, 1e-12);
  const Point2 p = layout.to_page_mm({2, 1});  // 8 mm right, 4 mm up (page y grows downwards)
  EXPECT_NEAR(p.x, 108, 1e-12);
  EXPECT_NEAR(p.y, 76, 1e-12);
}

TEST(SheetLayout, ScalesAreInWorldUnitsAtTheTarget) {
  OrthoParameters o;
  o.eye = {0, -10, 0};
  o.target = {0, 0, 0};
  o.height = 4;  // focal 2 / 4: a world unit is half a picture unit
  EXPECT_DOUBLE_EQ(world_per_picture_unit(ortho_camera(o), 0), 2);
  LookatParameters l;
  l.eye = {0, -10, 0};
  l.target = {0, 0, 0};
  l.fov_deg = 90;  // focal 1: at depth 10, a picture unit spans 10 world units
  EXPECT_NEAR(world_per_picture_unit(lookat_camera(l), 0), 10, 1e-12);
  // Without a target depth: the fallback depth.
  Camera c = lookat_camera(l);
  c.target_depth = 0;
  EXPECT_NEAR(world_per_picture_unit(c, 4), 4, 1e-12);
}

TEST(SheetLayout, TheTitleBlockSitsInTheFramesBottomRightCorner) {
  const SheetFrame a3 = sheet_frame(PageSpec{{420, 297}, 12});
  EXPECT_DOUBLE_EQ(a3.frame.xmin, 12);
  EXPECT_DOUBLE_EQ(a3.frame.ymax, 285);
  EXPECT_DOUBLE_EQ(a3.title_block.xmax, 408);
  EXPECT_DOUBLE_EQ(a3.title_block.ymax, 285);
  EXPECT_DOUBLE_EQ(a3.title_block.width(), 120);
  // A sheet too small for one has none.
  EXPECT_TRUE(sheet_frame(PageSpec{{80, 60}, 5}).title_block.empty());
}

// Third-angle views of a 60 × 40 × 20 part about its centre: front 60 × 20 (column 0, row 1), top 60 × 40
// (column 0, row 0), right 40 × 20 (column 1, row 1), iso 70 × 50 (column 1, row 0); labels 10 mm, gap 20.
std::vector<GridViewFit> third_angle() {
  return {{0, 1, {-30, -10, 30, 10}, 10, {}},
          {0, 0, {-30, -20, 30, 20}, 10, {}},
          {1, 1, {-20, -10, 20, 10}, 10, {}},
          {1, 0, {-35, -25, 35, 25}, 10, {}}};
}

TEST(SheetLayout, GridViewsLineUpByColumnAndRowAndCentreTheGrid) {
  const Rect2 area{0, 0, 300, 200};
  // At 1 mm per unit: columns 60 and 70 wide, rows 50 + 10 and 20 + 10 tall, 20 apart: the grid is 150 × 110,
  // its top-left corner at (75, 45). Column 0's targets at x 75 + 30, column 1's at 75 + 60 + 20 + 35; row
  // 0's at y 45 + 25 (its tallest view, the iso, reaches 25 above the target), row 1's at 45 + 60 + 20 + 10.
  const std::vector<Point2> at = grid_view_points(third_angle(), 1, area, 20);
  ASSERT_EQ(at.size(), 4U);
  EXPECT_DOUBLE_EQ(at[0].x, 105);
  EXPECT_DOUBLE_EQ(at[1].x, 105);
  EXPECT_DOUBLE_EQ(at[2].x, 190);
  EXPECT_DOUBLE_EQ(at[3].x, 190);
  EXPECT_DOUBLE_EQ(at[1].y, 70);
  EXPECT_DOUBLE_EQ(at[3].y, 70);
  EXPECT_DOUBLE_EQ(at[0].y, 135);
  EXPECT_DOUBLE_EQ(at[2].y, 135);
  // At 2 mm per unit the grid is 280 × 180: (10, 10) to (290, 190).
  const std::vector<Point2> at2 = grid_view_points(third_angle(), 2, area, 20);
  EXPECT_DOUBLE_EQ(at2[0].x - 2 * 30, 10);
  EXPECT_DOUBLE_EQ(at2[3].x + 2 * 35, 290);
  EXPECT_DOUBLE_EQ(at2[1].y - 2 * 25, 10);
  EXPECT_DOUBLE_EQ(at2[0].y + 2 * 10 + 10, 190);
}

TEST(SheetLayout, TheGridScaleIsTheLargestIsoScaleThatFits) {
  // 130 units wide with one 20 mm gap, 70 units tall with one gap and two 10 mm labels.
  EXPECT_DOUBLE_EQ(fitted_grid_scale(third_angle(), {0, 0, 300, 200}, 20), 2);    // 280/130, 160/70: 2.15
  EXPECT_DOUBLE_EQ(fitted_grid_scale(third_angle(), {0, 0, 280, 180}, 20), 2);    // exactly 2 by 2
  EXPECT_DOUBLE_EQ(fitted_grid_scale(third_angle(), {0, 0, 279, 180}, 20), 1);    // a hair too narrow
  EXPECT_DOUBLE_EQ(fitted_grid_scale(third_angle(), {0, 0, 1000, 200}, 20), 2);   // the height decides
  EXPECT_DOUBLE_EQ(fitted_grid_scale({}, {0, 0, 100, 100}, 20), 1);              // nothing to fit
  EXPECT_DOUBLE_EQ(fitted_grid_scale(third_angle(), {0, 0, 10, 10}, 20), 1);     // nothing positive fits
}

TEST(SheetLayout, GridCellsMakeRoomForTheDimensions) {
  // The third-angle grid of GridViewsLineUpByColumnAndRowAndCentreTheGrid, the front view's dimensions
  // reaching 12 mm below it and 15 mm right: row 1 grows by 12, column 0 by 15. At 1 mm per unit the grid
  // is 165 × 122, its corner at (67.5, 39); column 1's targets move right by 15, row 1's stay under their
  // row's top (the dimensions are below them).
  std::vector<GridViewFit> views = third_angle();
  views[0].dimensions = {0, 0, 15, 12};
  const std::vector<Point2> at = grid_view_points(views, 1, {0, 0, 300, 200}, 20);
  EXPECT_DOUBLE_EQ(at[0].x, 67.5 + 30);
  EXPECT_DOUBLE_EQ(at[2].x, 67.5 + 60 + 15 + 20 + 35);
  EXPECT_DOUBLE_EQ(at[1].y, 39 + 25);
  EXPECT_DOUBLE_EQ(at[0].y, 39 + 60 + 20 + 10);
  // The fit: across (W − 15 − 20)/130, down (H − 10 − 10 − 12 − 20)/70. In 295 × 200: 2 and 2.11 → 2; in
  // 295 × 190: down 1.97 → 1; in 290 × 200: across 1.96 → 1.
  EXPECT_DOUBLE_EQ(fitted_grid_scale(views, {0, 0, 295, 200}, 20), 2);
  EXPECT_DOUBLE_EQ(fitted_grid_scale(views, {0, 0, 295, 190}, 20), 1);
  EXPECT_DOUBLE_EQ(fitted_grid_scale(views, {0, 0, 290, 200}, 20), 1);
}

}  // namespace
}  // namespace hlr
