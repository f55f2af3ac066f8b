#include "core/device/formats/gcode_device.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/device/formats/devices.hpp"
#include "core/device/page/atomic_file.hpp"

namespace hlr {
namespace {

// A small machine with round numbers, so every expected line below is worked out by hand.
GcodeProfile small_servo() {
  GcodeProfile p;
  p.name = "small";
  p.info = "test machine";
  p.pen_mode = GcodePenMode::Servo;
  p.pen_up = 10;
  p.pen_down = 20;
  p.draw_feed_mm_min = 1000;
  p.travel_feed_mm_min = 3000;
  p.pen_down_dwell_s = 0.5;
  p.pen_up_dwell_s = 0.5;
  p.width_mm = 200;
  p.height_mm = 100;
  p.origin = GcodeOrigin::BottomLeft;
  p.pen_count = 2;
  return p;
}

PlotPage page(double w, double h, std::vector<PlotStroke> strokes) {
  PlotPage p;
  p.width_mm = w;
  p.height_mm = h;
  p.strokes = std::move(strokes);
  return p;
}

PlotStroke stroke(std::vector<Point2> pts, int pen = 1) {
  PlotStroke s;
  s.points = std::move(pts);
  s.pen = pen;
  return s;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The program without its header comments.
std::vector<std::string> code(const std::string& text) {
  std::vector<std::string> out;
  for (const std::string& l : lines(text))
    if (l.empty() || l[0] != '(' || l.find("change to pen") != std::string::npos) out.push_back(l);
  return out;
}

std::string error_of(const PlotPage& pg, const GcodeProfile& pr, const GcodeOptions& o = {}) {
  try {
    to_gcode(pg, pr, o);
  } catch (const DeviceError& e) {
    return e.what();
  }
  return "";
}

TEST(GcodeDevice, ServoProgramForOneStrokeOriginBottomLeft) {
  // Page 100 × 50 mm: machine y = 50 − page y.
  const std::string g = to_gcode(page(100, 50, {stroke({{10, 10}, {20, 10}, {20, 30}})}), small_servo());
  const std::vector<std::string> want = {
      "G21",
      "G90",
      "M3 S10",
      "G4 P0.5",  // pen up first, whatever the pen's state
      "G0 X10.000 Y40.000",
      "M3 S20",
      "G4 P0.5",
      "G1 X20.000 Y40.000 F1000",
      "G1 X20.000 Y20.000",
      "M3 S10",
      "G4 P0.5",
      "G0 X0.000 Y0.000",
      "M2",
  };
  EXPECT_EQ(code(g), want) << g;
  // Drawing 30 mm at 1000 mm/min = 1.8 s; travel √1700 + √800 = 69.515 mm at 3000 mm/min = 1.390 s; one
  // lift (0.5 + 0.5 s) and the first pen-up dwell 0.5 s: 4.69 s.
  EXPECT_NE(g.find("(estimated plotting time 4.7 s: drawing 30 mm at 1000 mm/min, travel 69.5 mm at 3000 "
                   "mm/min, pen lifts 1)"),
            std::string::npos)
      << g;
  EXPECT_EQ(lines(g).front(), "(hlrscript G-code for plotter 'small': test machine)");
}

TEST(GcodeDevice, AServoTurnedTheOtherWayEndsWithoutM2) {
  // M2 stops the spindle PWM: the servo turns to S0, below this pen's down value of 10.
  GcodeProfile p = small_servo();
  std::swap(p.pen_up, p.pen_down);
  const std::string g = to_gcode(page(100, 50, {stroke({{10, 10}, {20, 10}})}), p);
  const std::vector<std::string> c = code(g), all = lines(g);
  EXPECT_EQ(c[2], "M3 S20");  // pen up
  EXPECT_EQ(c.back(), "G0 X0.000 Y0.000");
  EXPECT_EQ(all.back(), "(end; no M2, which would turn the servo to S0 and lower the pen)");
}

TEST(GcodeDevice, TopLeftOriginKeepsPageY) {
  GcodeProfile p = small_servo();
  p.origin = GcodeOrigin::TopLeft;
  const std::vector<std::string> c = code(to_gcode(page(100, 50, {stroke({{10, 10}, {20.5, 30.25}})}), p));
  EXPECT_EQ(c[4], "G0 X10.000 Y10.000");
  EXPECT_EQ(c[7], "G1 X20.500 Y30.250 F1000");
  EXPECT_EQ(gcode_home_on_page(p, 100, 50), (Point2{0, 0}));
  EXPECT_EQ(gcode_home_on_page(small_servo(), 100, 50), (Point2{0, 50}));
}

TEST(GcodeDevice, ZAxisPenMovesAndNoZeroDwell) {
  GcodeProfile p = *gcode_profile_by_name("grbl-z");  // Z5 up, Z0 down at 600 mm/min, 0.05 s after lowering
  const std::vector<std::string> c = code(to_gcode(page(297, 210, {stroke({{0, 0}, {297, 210}})}), p));
  const std::vector<std::string> want = {"G21",
                                         "G90",
                                         "G0 Z5",
                                         "G0 X0.000 Y210.000",
                                         "G1 Z0 F600",
                                         "G4 P0.05",
                                         "G1 X297.000 Y0.000 F2000",
                                         "G0 Z5",
                                         "G0 X0.000 Y0.000",
                                         "M2"};
  EXPECT_EQ(c, want);
}

TEST(GcodeDevice, PenChangesPauseWithANamedPen) {
  // Pen 1 is in the holder at the start: a first stroke with pen 2 pauses before it.
  const PlotPage pg =
      page(100, 50, {stroke({{1, 1}, {2, 1}}, 2), stroke({{3, 1}, {4, 1}}, 2), stroke({{5, 1}, {6, 1}}, 1)});
  const std::string g = to_gcode(pg, small_servo());
  std::vector<std::string> pauses;
  const std::vector<std::string> all = lines(g);
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i] == "M0") pauses.push_back(all[i - 1] + " before " + all[i + 1]);
  const std::vector<std::string> want = {"(change to pen 2, then resume) before G0 X1.000 Y49.000",
                                         "(change to pen 1, then resume) before G0 X5.000 Y49.000"};
  EXPECT_EQ(pauses, want) << g;
  EXPECT_NE(g.find("pen changes, each an M0 pause: 2)"), std::string::npos);
  EXPECT_NE(g.find("pen changes not counted"), std::string::npos);
}

TEST(GcodeDevice, APenAboveThePenCountIsAnError) {
  const std::string e =
      error_of(page(100, 50, {stroke({{1, 1}, {2, 2}}), stroke({{1, 1}, {2, 2}}, 3)}), small_servo());
  EXPECT_NE(e.find("G-code: stroke 2 uses pen 3 but plotter 'small' has pens 1–2"), std::string::npos) << e;
}

TEST(GcodeDevice, APageLargerThanTheAreaIsRefusedWithTheArea) {
  const std::string big = error_of(page(297, 210, {}), small_servo());
  EXPECT_NE(
      big.find("G-code: the page is 297 × 210 mm but plotter 'small' draws within a 200 × 100 mm work area"),
      std::string::npos)
      << big;
  EXPECT_NE(big.find("smaller paper"), std::string::npos) << big;
  const std::string turned = error_of(page(90, 150, {}), small_servo());
  EXPECT_NE(turned.find("the page fits turned: use --landscape"), std::string::npos) << turned;
  EXPECT_THROW(gcode_home_on_page(small_servo(), 297, 210), DeviceError);
  EXPECT_EQ(error_of(page(200, 100, {}), small_servo()), "");  // exactly the area fits
}

TEST(GcodeDevice, APointOffThePageIsAnErrorUnlessClipped) {
  const PlotPage pg = page(100, 50, {stroke({{-5, 10}, {5, 10}, {5, 60}})});
  const std::string e = error_of(pg, small_servo());
  EXPECT_NE(
      e.find("G-code: stroke 1 reaches (-5, 10) mm on the page, off the 100 × 50 mm page plotter 'small' "
             "draws on"),
      std::string::npos)
      << e;
  EXPECT_NE(e.find("--clip"), std::string::npos) << e;
  GcodeOptions clip;
  clip.clip = true;
  // Cut at page x = 0 and at page y = 50 (machine y 0).
  const std::vector<std::string> c = code(to_gcode(pg, small_servo(), clip));
  EXPECT_EQ(c[4], "G0 X0.000 Y40.000");
  EXPECT_EQ(c[7], "G1 X5.000 Y40.000 F1000");
  EXPECT_EQ(c[8], "G1 X5.000 Y0.000");
}

TEST(GcodeDevice, NoNegativeZeroAndDotsAreDrawn) {
  // -0.0001 mm prints as 0.000; the second point prints as the first, so the stroke is a dot.
  const std::string g = to_gcode(page(100, 50, {stroke({{-0.0001, 50.0001}, {0.0002, 50}})}), small_servo());
  EXPECT_EQ(g.find("-0.000"), std::string::npos) << g;
  const std::vector<std::string> c = code(g);
  const std::vector<std::string> want = {"G21",    "G90",     "M3 S10", "G4 P0.5", "G0 X0.000 Y0.000",
                                         "M3 S20", "G4 P0.5", "M3 S10", "G4 P0.5", "G0 X0.000 Y0.000",
                                         "M2"};
  EXPECT_EQ(c, want) << g;
}

TEST(GcodeDevice, NonFinitePointsAndBadPagesAreErrors) {
  EXPECT_NE(error_of(page(100, 50, {stroke({{1, 1}, {NAN, 1}})}), small_servo()).find("not finite"),
            std::string::npos);
  EXPECT_NE(error_of(page(0, 50, {}), small_servo()).find("the page size must be positive"),
            std::string::npos);
  GcodeProfile bad = small_servo();
  bad.pen_down = bad.pen_up;
  EXPECT_NE(error_of(page(100, 50, {}), bad).find("the pen would never lift"), std::string::npos);
}

TEST(GcodeDevice, CommentsStayOneCommentPerLine) {
  GcodeProfile p = small_servo();
  p.info = "my (nested) plotter\nsecond line, 5 µm";
  for (const std::string& l : lines(to_gcode(page(100, 50, {}), p))) {
    if (l.empty() || l[0] != '(') continue;
    EXPECT_EQ(l.back(), ')') << l;
    EXPECT_EQ(l.find('(', 1), std::string::npos) << l;
    EXPECT_EQ(l.find(')'), l.size() - 1) << l;
    for (const char c : l) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << l;
  }
}

TEST(GcodeDevice, DeviceKindAndPlanning) {
  EXPECT_EQ(device_kind_for("a.gcode"), DeviceKind::Gcode);
  EXPECT_EQ(device_kind_for("a.NC"), DeviceKind::Gcode);
  EXPECT_EQ(device_kind_for("a.ngc"), DeviceKind::Gcode);
  EXPECT_STREQ(device_kind_name(DeviceKind::Gcode), "G-code");
  EXPECT_TRUE(one_frame_per_file(DeviceKind::Gcode));
  const auto device = make_gcode_device(*gcode_profile_by_name("grbl-servo"));
  EXPECT_TRUE(device->one_frame_per_file());
  const DevicePlanning plan = device->planning(297, 210);
  EXPECT_EQ(plan.grid_mm, 0.025);
  EXPECT_EQ(plan.home, (Point2{0, 210}));
  EXPECT_DOUBLE_EQ(plan.speeds.pen_down_mm_per_s, 2000.0 / 60);
  EXPECT_THROW(device->planning(500, 300), DeviceError);
  GcodeProfile bad = small_servo();
  bad.pen_count = 0;
  EXPECT_THROW(make_gcode_device(bad), DeviceError);
}

}  // namespace
}  // namespace hlr
