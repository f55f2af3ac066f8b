#include "core/device/plotters/gcode_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/device/page/atomic_file.hpp"

namespace hlr {
namespace {

std::string error_of(const GcodeProfile& p) {
  try {
    check_gcode_profile(p);
  } catch (const DeviceError& e) {
    return e.what();
  }
  return "";
}

TEST(GcodeProfile, BuiltinsAreFoundIgnoringCaseAndPassTheirCheck) {
  EXPECT_EQ(gcode_profile_list(), "grbl-servo, grbl-z");
  ASSERT_TRUE(gcode_profile_by_name("GRBL-Servo"));
  EXPECT_EQ(gcode_profile_by_name("GRBL-Servo")->name, "grbl-servo");
  EXPECT_EQ(gcode_profile_by_name("grbl-z")->pen_mode, GcodePenMode::ZAxis);
  EXPECT_FALSE(gcode_profile_by_name("grbl"));
  EXPECT_FALSE(gcode_profile_by_name("hp7475a"));
  for (const GcodeProfile& p : builtin_gcode_profiles()) {
    EXPECT_EQ(error_of(p), "") << p.name;
    EXPECT_FALSE(p.info.empty()) << p.name;
  }
  const GcodeProfile servo = *gcode_profile_by_name("grbl-servo");
  EXPECT_EQ(servo.pen_mode, GcodePenMode::Servo);
  EXPECT_EQ(servo.origin, GcodeOrigin::BottomLeft);
  EXPECT_DOUBLE_EQ(servo.pen_up_dwell_s, 0.15);
  const GcodeProfile z = *gcode_profile_by_name("grbl-z");
  EXPECT_DOUBLE_EQ(z.pen_up, 5);
  EXPECT_DOUBLE_EQ(z.pen_down, 0);
}

TEST(GcodeProfile, CheckNamesTheFirstProblem) {
  GcodeProfile p = *gcode_profile_by_name("grbl-servo");
  p.name = "mine";
  GcodeProfile q = p;
  q.pen_down = q.pen_up;
  EXPECT_NE(error_of(q).find("plotter 'mine': pen up and pen down are both S30"), std::string::npos)
      << error_of(q);
  q = p;
  q.pen_up = -1;
  EXPECT_NE(error_of(q).find("the pen-up position must be an S value from 0"), std::string::npos)
      << error_of(q);
  q = p;
  q.pen_down = std::nan("");
  EXPECT_NE(error_of(q).find("the pen-down position"), std::string::npos) << error_of(q);
  q = p;
  q.draw_feed_mm_min = 0;
  EXPECT_NE(error_of(q).find("the drawing feed must be 1 to 100000 mm/min, not 0"), std::string::npos)
      << error_of(q);
  q = p;
  q.travel_feed_mm_min = 1e6;
  EXPECT_NE(error_of(q).find("the travel feed"), std::string::npos) << error_of(q);
  q = p;
  q.pen_up_dwell_s = -0.5;
  EXPECT_NE(error_of(q).find("a dwell must be 0 to 10 seconds, not -0.5"), std::string::npos) << error_of(q);
  q = p;
  q.height_mm = 0;
  EXPECT_NE(error_of(q).find("the work area must be above 0"), std::string::npos) << error_of(q);
  q = p;
  q.pen_count = 0;
  EXPECT_NE(error_of(q).find("the pen count must be 1 to 255, not 0"), std::string::npos) << error_of(q);

  GcodeProfile z = *gcode_profile_by_name("grbl-z");
  z.name = "cnc";
  z.pen_up = -1;  // below pen-down Z 0: the pen would lift into the paper
  EXPECT_NE(error_of(z).find("plotter 'cnc': pen-up Z (-1 mm) must be above pen-down Z (0 mm)"),
            std::string::npos)
      << error_of(z);
  z = *gcode_profile_by_name("grbl-z");
  z.z_feed_mm_min = 0.5;
  EXPECT_NE(error_of(z).find("the Z feed"), std::string::npos) << error_of(z);
}

TEST(GcodeProfile, SpeedsComeFromFeedsDwellsAndTheZMoves) {
  const PlotterSpeeds s = gcode_speeds(*gcode_profile_by_name("grbl-servo"));
  EXPECT_DOUBLE_EQ(s.pen_down_mm_per_s, 2000.0 / 60);
  EXPECT_DOUBLE_EQ(s.pen_up_mm_per_s, 5000.0 / 60);
  EXPECT_DOUBLE_EQ(s.lift_s, 0.3);
  // Z: 5 mm down at 600 mm/min (0.5 s), 5 mm up at 5000 mm/min (0.06 s), 0.05 s dwell after lowering.
  const PlotterSpeeds z = gcode_speeds(*gcode_profile_by_name("grbl-z"));
  EXPECT_NEAR(z.lift_s, 0.61, 1e-12);
}

}  // namespace
}  // namespace hlr
