// G-code profiles for GRBL pen plotters: how the pen is lifted (a hobby servo on the spindle's PWM
// output, or a Z axis), how fast the machine draws and travels, how long it waits for the pen to settle,
// the work area and where its origin lies, and how many pens the user may swap in. Built-in profiles
// are starting points (see gcode_profile.cpp for where each number comes from); scripts declare their
// own with `plotter NAME { base: "grbl-servo", … }`.
//
// Machine coordinates: millimetres from the work area's origin corner. With the origin at the
// bottom-left (GRBL's default homing on most pen plotters) machine y grows up, away from the user; with
// it at the top-left machine y grows down, as page y does.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/plan/pen_plan.hpp"

namespace hlr {

enum class GcodePenMode {
  Servo,  // pen up `M3 S<up>`, down `M3 S<down>`: a servo driven by the spindle PWM (GRBL servo builds)
  ZAxis,  // pen up `G0 Z<up>`, down `G1 Z<down> F<z feed>`: the pen on a Z axis (a CNC machine)
};

enum class GcodeOrigin {
  BottomLeft,  // machine (0, 0) at the area's bottom-left corner, y up (GRBL's default)
  TopLeft,     // machine (0, 0) at the area's top-left corner, y down
};

struct GcodeProfile {
  std::string name;  // "grbl-servo"
  std::string info;  // one line for --help and errors
  GcodePenMode pen_mode = GcodePenMode::Servo;
  double pen_up = 30, pen_down = 60;  // Servo: spindle S values; ZAxis: Z in mm
  double z_feed_mm_min = 600;         // ZAxis: the pen-down Z move's feed
  double draw_feed_mm_min = 2000;     // G1 feed while drawing
  double travel_feed_mm_min = 5000;   // G0 moves run at the machine's rapid rate: this is for the estimate
  double pen_down_dwell_s = 0.15;     // G4 after lowering the pen (0: none)
  double pen_up_dwell_s = 0.15;       // G4 after lifting it
  double width_mm = 420, height_mm = 297;  // the work area the pen reaches
  GcodeOrigin origin = GcodeOrigin::BottomLeft;
  int pen_count = 8;  // pens are changed by hand at an M0 pause: how many the drawing may use
};

// grbl-servo, grbl-z.
const std::vector<GcodeProfile>& builtin_gcode_profiles();
std::optional<GcodeProfile> gcode_profile_by_name(std::string_view name);  // case-insensitive
std::string gcode_profile_list();  // "grbl-servo, grbl-z", for messages

// Throws DeviceError naming the first problem: pen positions that are not finite or (servo) negative,
// up equal to down (servo) or not above it (Z), feeds not within 1…kMaxGcodeFeedMmMin, dwells not within
// 0…kMaxGcodeDwellS, a work area side not within (0, kMaxPaperSideMm], pens outside 1…kMaxPen.
void check_gcode_profile(const GcodeProfile& profile);

// What the time estimate and the pen plan use: feeds in mm/s and one lift's time (both dwells and, for a
// Z pen, the Z moves down at z feed and up at the travel feed).
PlotterSpeeds gcode_speeds(const GcodeProfile& profile);

// "bottom-left" or "top-left".
const char* gcode_origin_name(GcodeOrigin origin);

}  // namespace hlr
