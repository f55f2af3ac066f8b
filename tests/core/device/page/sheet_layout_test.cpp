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
  const SheetViewFit a{{100, 60}, std::nullopt, Rect2{-10, -20, 30, 5}, 8};
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a}, spec), 5);
  // The paper's scale wins.
  PageSpec scaled = spec;
  scaled.mm_per_unit = 0.25;
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a}, scaled), 0.25);
  // Nothing to fit: 1.
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({}, spec), 1);
  // A point outside the margins constrains nothing.
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({{{5, 60}, std::nullopt, Rect2{-1, -1, 1, 1}, 0}}, spec), 1);
}

TEST(SheetLayout, FittedViewsKeepClearOfOneAnotherAndOfTheTitleBlock) {
  const PageSpec spec{{297, 210}, 10};
  // Two views 100 mm apart along x, each reaching 10 units towards the other: side by side with the 5 mm
  // gap, 20·s + 5 ≤ 100, s ≤ 4.75 (apart along y they cannot be: they share a row). ISO: 2.
  const SheetViewFit a{{100, 100}, std::nullopt, Rect2{-10, -5, 10, 5}, 0};
  const SheetViewFit b{{200, 100}, std::nullopt, Rect2{-10, -5, 10, 5}, 0};
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a, b}, spec), 2);
  // b at a scale of its own, 3 mm per unit: 10·s + 30 + 5 ≤ 100, s ≤ 6.5; a's margins: (100 − 10)/10 = 9,
  // (100 − 10)/5 = 18. ISO: 5.
  SheetViewFit fixed = b;
  fixed.mm_per_unit = 3;
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a, fixed}, spec), 5);
  // Diagonal neighbours may be apart along either axis; the freer one counts. c at (200, 180), 80 mm
  // below on a taller sheet: along y 10·s + 5 ≤ 80 (s ≤ 7.5) beats along x (s ≤ 4.75); a's own margins
  // allow 9, c's (287 − 200)/10 = 8.7. ISO: 5.
  const SheetViewFit c{{200, 180}, std::nullopt, Rect2{-10, -5, 10, 5}, 0};
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a, c}, PageSpec{{297, 300}, 10}), 5);
  // The title block at x ≥ 150, y ≥ 150: a view at (100, 100) reaching 10 units right and 5 down stays to
  // its left (10·s + 5 ≤ 50, s ≤ 4.5) or above it (5·s + 5 ≤ 50, s ≤ 9): 9 → its margins' 9 → ISO 5.
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({a}, spec, Rect2{150, 150, 287, 200}), 5);
  // Reaching 20 units right and 10 down: left 45/20 = 2.25, above 45/10 = 4.5 → ISO 2.
  const SheetViewFit wide{{100, 100}, std::nullopt, Rect2{-5, -10, 20, 5}, 0};
  EXPECT_DOUBLE_EQ(fitted_sheet_scale({wide}, spec, Rect2{150, 150, 287, 200}), 2);
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

}  // namespace
}  // namespace hlr
