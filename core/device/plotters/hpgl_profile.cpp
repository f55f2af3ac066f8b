#include "core/device/plotters/hpgl_profile.hpp"

#include <cmath>

#include "core/device/page/atomic_file.hpp"
#include "core/device/plotters/profile_lookup.hpp"
#include "core/format_number.hpp"
#include "core/limits.hpp"

namespace hlr {
namespace {

// Sources, as cited below:
//  [HP7475]  HP 7475A Interfacing and Programming Manual: the hard-clip ranges in plotter units per paper
//            (also in vpype's device table), the default P1/P2 per paper and the statement that the
//            P1/P2 frame is centred on the sheet; 38.1 cm/s maximum pen speed.
//  [vpype]   vpype's vpype_config.toml (prior-art.md §5): 0.02488 mm calibrated unit for the HP desktop
//            plotters, pen counts, and `origin_location` (where plotter (0, 0) sits on the sheet),
//            measured by owners of the plotters.
//  [cursor]  a third-party plotting library's per-plotter bounds table: 0–15970 × 0–10870 for the HP
//            7550A (paper not named; the size of A3/B); its max-speed table gives 80 cm/s for the 7550A.
//  "estimate": no manual at hand; a conservative guess that keeps the pen on the sheet.
// The unit is the plotter's real step; HP's nominal unit is 0.025 mm, vpype's 0.02488 mm is a
// calibration of the HP desktop plotters that makes drawings come out at their true size.

constexpr double kHpUnit = 0.02488;     // [vpype]
constexpr double kNominalUnit = 0.025;  // HP-GL reference (prior-art.md §10), Roland RD-GL I step

// A range whose sheet offsets are unknown: the reachable area centred on the sheet.
HpglPaperRange centred(std::string paper, double w, double h, long x_max, long y_max, double unit) {
  return {std::move(paper), w, h, 0, x_max, 0, y_max, 0.5 * (w - x_max * unit), 0.5 * (h - y_max * unit)};
}

std::vector<HpglProfile> make_profiles() {
  std::vector<HpglProfile> all;

  // HP 7475A: 6 pens, A4/A3 with the plotter's rear switch in metric mode, Letter/Tabloid (B) in English.
  HpglProfile hp7475a;
  hp7475a.name = "hp7475a";
  hp7475a.info = "HP 7475A, 6 pens; A4/A3 need the metric switch setting, Letter/Tabloid the English one";
  hp7475a.unit_mm = kHpUnit;
  hp7475a.pen_count = 6;  // [HP7475], [vpype]
  hp7475a.ranges = {
      // Ranges [HP7475]. Origins [vpype] (origin_location 10/206, 15/287 and 10/211 mm from the top-left
      // corner, turned into mm from the bottom-left): they agree within 1.7 mm with the origins implied by
      // [HP7475]'s centred default P1/P2. The reachable area is not centred on the sheet: A4 needs a
      // 13.9 mm margin at the top, A3 15 mm at the left.
      {"A4", 297, 210, 0, 11040, 0, 7721, 10, 4},
      {"A3", 420, 297, 0, 16158, 0, 11040, 15, 10},
      {"Letter", 279.4, 215.9, 0, 10365, 0, 7962, 10, 4.9},
      // vpype repeats A3's origin for B (287 mm from the top of a 279.4 mm sheet: off the sheet), so the
      // origin comes from [HP7475]'s B default P1/P2 (522,259)–(15722,10259) centred on the sheet.
      {"Tabloid", 431.8, 279.4, 0, 16640, 0, 10365, 13.8, 8.9},
  };
  hp7475a.speeds = {381, 381, 0.1};  // 38.1 cm/s [HP7475] up and down; lift time an estimate
  all.push_back(hp7475a);

  // HP 7440A ColorPro: 8 pens, A4 and Letter only.
  HpglProfile hp7440a;
  hp7440a.name = "hp7440a";
  hp7440a.info = "HP 7440A ColorPro, 8 pens; A4 needs the metric DIP switch setting";
  hp7440a.unit_mm = kHpUnit;
  hp7440a.pen_count = 8;  // [vpype]
  hp7440a.ranges = {
      {"A4", 297, 210, 0, 11040, 0, 7721, 15, 10},  // range and origin (15/200 mm from top-left) [vpype]
      // Estimate: the 7475A's documented Letter range, centred (no ColorPro figures at hand).
      centred("Letter", 279.4, 215.9, 10365, 7962, kHpUnit),
  };
  hp7440a.speeds = {381, 381, 0.1};  // estimate: the 7475A's speeds
  all.push_back(hp7440a);

  // HP 7550A: 8 pens, sheet feeder for A/A4, manual B/A3.
  HpglProfile hp7550;
  hp7550.name = "hp7550";
  hp7550.info =
      "HP 7550A, 8 pens; ranges are conservative (query OH; on your plotter and declare a plotter "
      "block for exact ones)";
  hp7550.unit_mm = kHpUnit;
  hp7550.pen_count = 8;
  hp7550.ranges = {
      // A3/B: [cursor]'s 0–15970 × 0–10870 for both. A4/Letter: estimate, 0–10870 along the 297 mm side
      // (A3's short side) and the 7475A's A4 7721 scaled by 10870/11040 → 7600. Offsets unknown: centred.
      centred("A4", 297, 210, 10870, 7600, kHpUnit),
      centred("A3", 420, 297, 15970, 10870, kHpUnit),
      centred("Letter", 279.4, 215.9, 10870, 7600, kHpUnit),
      centred("Tabloid", 431.8, 279.4, 15970, 10870, kHpUnit),
  };
  hp7550.speeds = {800, 800, 0.1};  // 80 cm/s [cursor]; lift time an estimate
  all.push_back(hp7550);

  // Roland DXY-1100/1200/1300 (RD-GL I mode, 0.025 mm step): a flatbed for sheets up to A3.
  HpglProfile dxy;
  dxy.name = "roland-dxy";
  dxy.info =
      "Roland DXY-1300 class, 8 pens, DIP switches set to RD-GL (HP-GL) mode; ranges are conservative "
      "estimates";
  dxy.unit_mm = kNominalUnit;
  dxy.pen_count = 8;
  dxy.ranges = {
      // Estimates: A3 380 × 270 mm centred (the smaller figure quoted for this class), A4 a 10 mm border.
      centred("A4", 297, 210, 11080, 7600, kNominalUnit),
      centred("A3", 420, 297, 15200, 10800, kNominalUnit),
  };
  dxy.speeds = {420, 420, 0.1};  // estimate (42 cm/s is the figure quoted for this class)
  all.push_back(dxy);

  // Plain HP-GL for viewers, converters and cutters: origin at the sheet's bottom-left corner (HP-GL/2's
  // convention), any page up to 32767 units (819 mm) a side, a newline after each command.
  HpglProfile generic;
  generic.name = "generic";
  generic.info =
      "plain HP-GL, 0.025 mm units, origin at the bottom-left corner of the page, any page size up "
      "to 819 mm a side";
  generic.unit_mm = kNominalUnit;
  generic.pen_count = 8;
  generic.ranges = {{"any", 0, 0, 0, 32767, 0, 32767, 0, 0}};
  generic.newline = true;
  all.push_back(generic);
  return all;
}

std::string mm(double v) { return format_mm_for_message(v); }

}  // namespace

const std::vector<HpglProfile>& builtin_hpgl_profiles() {
  static const std::vector<HpglProfile> profiles = make_profiles();
  return profiles;
}

std::optional<HpglProfile> hpgl_profile_by_name(std::string_view name) {
  return profile_by_name(builtin_hpgl_profiles(), name);
}

std::string hpgl_profile_list() { return profile_names(builtin_hpgl_profiles()); }

std::string hpgl_paper_list(const HpglProfile& profile) {
  std::string list;
  for (const HpglPaperRange& r : profile.ranges) {
    if (!list.empty()) list += ", ";
    if (r.any_size())
      list += "any size";
    else
      list += r.paper + " (" + mm(r.width_mm) + " × " + mm(r.height_mm) + " mm)";
  }
  return list;
}

void check_hpgl_profile(const HpglProfile& p) {
  const std::string who = "plotter '" + p.name + "': ";
  if (!(std::isfinite(p.unit_mm) && p.unit_mm > 0))
    throw DeviceError(who + "the unit must be a positive length in mm, not " + format_for_message(p.unit_mm));
  if (p.ranges.empty()) throw DeviceError(who + "no paper range");
  for (const HpglPaperRange& r : p.ranges) {
    const std::string where = who + "paper '" + r.paper + "': ";
    if (!r.any_size() &&
        !(std::isfinite(r.width_mm) && std::isfinite(r.height_mm) && r.width_mm > 0 && r.height_mm > 0))
      throw DeviceError(where + "the sheet size must be positive (or 0 × 0 for any size)");
    if (!(std::isfinite(r.origin_x_mm) && std::isfinite(r.origin_y_mm)))
      throw DeviceError(where + "the origin offset must be finite");
    const auto in16 = [](long v) { return v >= kHpglMinCoordinate && v <= kHpglMaxCoordinate; };
    if (!(in16(r.x_min) && in16(r.x_max) && in16(r.y_min) && in16(r.y_max)))
      throw DeviceError(where + "the range must lie within " + std::to_string(kHpglMinCoordinate) + "…" +
                        std::to_string(kHpglMaxCoordinate) + " plotter units");
    if (!(r.x_min < r.x_max && r.y_min < r.y_max))
      throw DeviceError(where + "the range is empty (x " + std::to_string(r.x_min) + "…" +
                        std::to_string(r.x_max) + ", y " + std::to_string(r.y_min) + "…" +
                        std::to_string(r.y_max) + ")");
  }
  if (p.pen_count < 1) throw DeviceError(who + "needs at least one pen");
  if (p.velocity_cm_s && !(*p.velocity_cm_s >= kMinVelocityCmS && *p.velocity_cm_s <= kMaxVelocityCmS))
    throw DeviceError(who + "the velocity must be " + format_for_message(kMinVelocityCmS) + "…" +
                      format_for_message(kMaxVelocityCmS) + " cm/s");
  if (p.max_pairs_per_pd < 1) throw DeviceError(who + "at least one coordinate pair per PD is needed");
}

}  // namespace hlr
