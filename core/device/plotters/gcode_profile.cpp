#include "core/device/plotters/gcode_profile.hpp"

#include <cmath>

#include "core/device/page/atomic_file.hpp"
#include "core/device/plotters/profile_lookup.hpp"
#include "core/format_number.hpp"
#include "core/limits.hpp"

namespace hlr {
namespace {

// Sources. There is no manual for "a GRBL pen plotter": every machine is tuned by its owner, so the
// built-in profiles are starting points to copy and adjust with `plotter NAME { base: …, up: …, … }`.
//  - Servo pens: GRBL servo builds (the servo on the spindle PWM pin, spindle_control.c replaced) take
//    `M3 S<value>` for both positions; S30 up and S60 down sit in the middle of the range most of these
//    builds map to a hobby servo's travel. Estimate: calibrate yours.
//  - Dwell: a hobby servo needs about 0.1–0.2 s to move the pen and let it settle (servo plotter
//    firmwares wait ~150 ms after each servo command), so 0.15 s after each lift and drop.
//  - Origin: GRBL homes pen plotters to the bottom-left corner with +Y away from the user.
//  - Area: A3 landscape (420 × 297 mm), the common size of hobby and kit servo plotters. Estimate.
//  - Feeds: 2000 mm/min drawing is what fibre-tip pens take without skipping on these machines; G0
//    moves run at GRBL's rapid rate ($110/$111), for the estimate taken as 5000 mm/min. Estimates.
//  - Z pen: a CNC machine holding a pen, 5 mm above the work surface to travel and at Z0 to draw, the
//    Z feed slow enough (600 mm/min) not to stab the paper; dwells are short (a Z move has settled when
//    it ends).

std::vector<GcodeProfile> make_profiles() {
  std::vector<GcodeProfile> all;

  GcodeProfile servo;
  servo.name = "grbl-servo";
  servo.info =
      "GRBL servo pen plotter, A3 landscape area, origin bottom-left, pen up M3 S30, down M3 S60, "
      "0.15 s dwell";
  servo.pen_mode = GcodePenMode::Servo;
  servo.pen_up = 30;
  servo.pen_down = 60;
  servo.pen_down_dwell_s = 0.15;
  servo.pen_up_dwell_s = 0.15;
  all.push_back(servo);

  GcodeProfile z;
  z.name = "grbl-z";
  z.info = "GRBL machine with the pen on Z (up Z5, down Z0), A3 landscape area, origin bottom-left";
  z.pen_mode = GcodePenMode::ZAxis;
  z.pen_up = 5;
  z.pen_down = 0;
  z.z_feed_mm_min = 600;
  z.pen_down_dwell_s = 0.05;
  z.pen_up_dwell_s = 0;
  all.push_back(z);
  return all;
}

std::string num(double v) { return format_for_message(v); }

}  // namespace

const std::vector<GcodeProfile>& builtin_gcode_profiles() {
  static const std::vector<GcodeProfile> profiles = make_profiles();
  return profiles;
}

std::optional<GcodeProfile> gcode_profile_by_name(std::string_view name) {
  return profile_by_name(builtin_gcode_profiles(), name);
}

std::string gcode_profile_list() { return profile_names(builtin_gcode_profiles()); }

const char* gcode_origin_name(GcodeOrigin origin) {
  return origin == GcodeOrigin::BottomLeft ? "bottom-left" : "top-left";
}

void check_gcode_profile(const GcodeProfile& p) {
  const std::string who = "plotter '" + p.name + "': ";
  const bool servo = p.pen_mode == GcodePenMode::Servo;
  const auto position_ok = [&](double v) {
    return std::isfinite(v) && (servo ? v >= 0 && v <= kMaxGcodeSpindle : std::fabs(v) <= kMaxGcodeZMm);
  };
  const std::string range =
      servo ? "an S value from 0 to " + num(kMaxGcodeSpindle)
            : "a Z position from " + num(-kMaxGcodeZMm) + " to " + num(kMaxGcodeZMm) + " mm";
  if (!position_ok(p.pen_up))
    throw DeviceError(who + "the pen-up position must be " + range + ", not " + num(p.pen_up));
  if (!position_ok(p.pen_down))
    throw DeviceError(who + "the pen-down position must be " + range + ", not " + num(p.pen_down));
  if (servo && p.pen_up == p.pen_down)
    throw DeviceError(who + "pen up and pen down are both S" + num(p.pen_up) + ": the pen would never lift");
  if (!servo && !(p.pen_up > p.pen_down))
    throw DeviceError(who + "pen-up Z (" + num(p.pen_up) + " mm) must be above pen-down Z (" +
                      num(p.pen_down) + " mm)");
  const auto feed_ok = [](double f) { return f >= kMinGcodeFeedMmMin && f <= kMaxGcodeFeedMmMin; };
  const std::string feeds = num(kMinGcodeFeedMmMin) + " to " + num(kMaxGcodeFeedMmMin) + " mm/min";
  if (!feed_ok(p.draw_feed_mm_min))
    throw DeviceError(who + "the drawing feed must be " + feeds + ", not " + num(p.draw_feed_mm_min));
  if (!feed_ok(p.travel_feed_mm_min))
    throw DeviceError(who + "the travel feed must be " + feeds + ", not " + num(p.travel_feed_mm_min));
  if (!servo && !feed_ok(p.z_feed_mm_min))
    throw DeviceError(who + "the Z feed must be " + feeds + ", not " + num(p.z_feed_mm_min));
  const auto dwell_ok = [](double s) { return s >= 0 && s <= kMaxGcodeDwellS; };
  if (!dwell_ok(p.pen_down_dwell_s) || !dwell_ok(p.pen_up_dwell_s))
    throw DeviceError(who + "a dwell must be 0 to " + num(kMaxGcodeDwellS) + " seconds, not " +
                      num(dwell_ok(p.pen_down_dwell_s) ? p.pen_up_dwell_s : p.pen_down_dwell_s));
  const auto side_ok = [](double v) { return v > 0 && v <= kMaxPaperSideMm; };
  if (!side_ok(p.width_mm) || !side_ok(p.height_mm))
    throw DeviceError(who + "the work area must be above 0 and at most " + num(kMaxPaperSideMm) +
                      " mm a side, not " + num(p.width_mm) + " × " + num(p.height_mm) + " mm");
  if (p.pen_count < 1 || p.pen_count > kMaxPen)
    throw DeviceError(who + "the pen count must be 1 to " + std::to_string(kMaxPen) + ", not " +
                      std::to_string(p.pen_count));
}

PlotterSpeeds gcode_speeds(const GcodeProfile& p) {
  PlotterSpeeds s;
  s.pen_down_mm_per_s = p.draw_feed_mm_min / 60;
  s.pen_up_mm_per_s = p.travel_feed_mm_min / 60;
  s.lift_s = p.pen_down_dwell_s + p.pen_up_dwell_s;
  if (p.pen_mode == GcodePenMode::ZAxis) {  // down at the Z feed, up as a rapid
    const double dz = std::fabs(p.pen_up - p.pen_down);
    s.lift_s += dz / p.z_feed_mm_min * 60 + dz / p.travel_feed_mm_min * 60;
  }
  return s;
}

}  // namespace hlr
