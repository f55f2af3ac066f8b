// G-code plotter declarations: `plotter NAME { base: "grbl-servo" | "grbl-z", ... }` — the profile the
// evaluator records, and every mistake as an error at its place.
#include <gtest/gtest.h>

#include <string>

#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

TEST(GcodePlotter, ServoDeclarationAppliesEveryKey) {
  const FrameScene scene = test::run_ok(
      "plotter myplot { base: \"grbl-servo\", up: 40, down: 90, feed: 3000, travel: 6000, dwell: 0.2,\n"
      "  width: 300, height: 200, origin: \"top-left\", pens: 2, dwell_up: 0.3 }");
  ASSERT_EQ(scene.plotters.size(), 1U);
  const PlotterSetting& s = scene.plotters[0];
  EXPECT_EQ(s.profile.name, "myplot");
  ASSERT_TRUE(s.gcode);
  const GcodeProfile& p = *s.gcode;
  EXPECT_EQ(p.name, "myplot");
  EXPECT_EQ(p.pen_mode, GcodePenMode::Servo);
  EXPECT_EQ(p.pen_up, 40);
  EXPECT_EQ(p.pen_down, 90);
  EXPECT_EQ(p.draw_feed_mm_min, 3000);
  EXPECT_EQ(p.travel_feed_mm_min, 6000);
  EXPECT_EQ(p.pen_down_dwell_s, 0.2);
  EXPECT_EQ(p.pen_up_dwell_s, 0.3);  // dwell_up after dwell: the more specific key wins, in any order
  EXPECT_EQ(p.width_mm, 300);
  EXPECT_EQ(p.height_mm, 200);
  EXPECT_EQ(p.origin, GcodeOrigin::TopLeft);
  EXPECT_EQ(p.pen_count, 2);
  EXPECT_EQ(p.info, "declared in the script, based on grbl-servo");
}

TEST(GcodePlotter, ZDeclarationKeepsTheBaseWhereNotGiven) {
  const FrameScene scene =
      test::run_ok("plotter cnc { base: \"GRBL-Z\", z_up: 3, z_down: -0.5, z_feed: 300 }");
  ASSERT_TRUE(scene.plotters[0].gcode);
  const GcodeProfile& p = *scene.plotters[0].gcode;
  EXPECT_EQ(p.pen_mode, GcodePenMode::ZAxis);
  EXPECT_EQ(p.pen_up, 3);
  EXPECT_EQ(p.pen_down, -0.5);
  EXPECT_EQ(p.z_feed_mm_min, 300);
  const GcodeProfile base = *gcode_profile_by_name("grbl-z");
  EXPECT_EQ(p.draw_feed_mm_min, base.draw_feed_mm_min);
  EXPECT_EQ(p.width_mm, base.width_mm);
  EXPECT_EQ(p.origin, GcodeOrigin::BottomLeft);
  // An HPGL declaration has no G-code profile.
  EXPECT_FALSE(test::run_ok("plotter h { base: \"hp7475a\" }").plotters[0].gcode);
}

struct Case {
  const char* script;
  const char* expected;
};

// clang-format off
const Case kErrors[] = {
  {"plotter m { base: \"grbl-z\", up: 5 }", "1:29: plotter 'm': unknown key 'up'"},
  {"plotter m { base: \"grbl-servo\", z_up: 5 }", "1:33: plotter 'm': unknown key 'z_up'"},
  {"plotter m { base: \"grbl-servo\", unit: 0.1 }", "1:33: plotter 'm': unknown key 'unit'"},
  {"plotter m { base: \"hp7475a\", feed: 3000 }", "1:30: plotter 'm': unknown key 'feed'"},
  {"plotter m { base: \"grbl-servo\", up: -1 }", "1:33: plotter 'm': key 'up' must be an S value from 0 to 100000 (got -1)"},
  {"plotter m { base: \"grbl-servo\", up: 50, down: 50 }", "1:41: plotter 'm': pen up and pen down are both S50: the pen would never lift"},
  {"plotter m { base: \"grbl-z\", z_down: 6 }", "1:29: plotter 'm': pen-up Z (5 mm) must be above pen-down Z (6 mm)"},
  {"plotter m { base: \"grbl-servo\", feed: 0 }", "1:33: plotter 'm': key 'feed' must be from 1 to 100000 mm/min (got 0)"},
  {"plotter m { base: \"grbl-servo\", dwell: 11 }", "1:33: plotter 'm': key 'dwell' must be from 0 to 10 seconds (got 11)"},
  {"plotter m { base: \"grbl-servo\", width: 0 }", "1:33: plotter 'm': key 'width' must be above 0 and at most 10000 mm (got 0)"},
  {"plotter m { base: \"grbl-servo\", origin: \"centre\" }", "1:33: plotter 'm': key 'origin' must be \"bottom-left\" or \"top-left\", got \"centre\""},
  {"plotter m { base: \"grbl-servo\", pens: 0 }", "1:33: plotter 'm': key 'pens' must be a whole number from 1 to 255 (got 0)"},
  {"plotter m { base: \"grbl-servo\", feed: \"fast\" }", "1:33: plotter 'm': key 'feed' must be a number, got a string"},
};
// clang-format on

TEST(GcodePlotter, Errors) {
  for (const Case& c : kErrors) EXPECT_EQ(test::first_error(c.script), c.expected) << c.script;
  const std::string base = test::printed_error("plotter m { base: \"grbl-sevro\" }");
  EXPECT_NE(base.find("did you mean 'grbl-servo'?"), std::string::npos) << base;
  EXPECT_NE(base.find("grbl-servo, grbl-z (G-code)"), std::string::npos) << base;
  const std::string key = test::printed_error("plotter m { base: \"grbl-z\", up: 5 }");
  EXPECT_NE(key.find("z_up: and z_down:"), std::string::npos) << key;
}

}  // namespace
}  // namespace hlr::runtime
