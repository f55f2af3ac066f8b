// HPGL plotter profiles: what a plotter accepts (unit, paper ranges, where the pen can reach on each
// sheet, pens, velocity) and how we write for it (relative or absolute moves, pairs per PD, a newline
// after each command). Built-in profiles follow the devices' manuals and vpype's device table
// (prior-art.md §5, §10); scripts declare their own with `plotter NAME { … }`.
//
// Sheet geometry. A range describes one paper size as loaded: `width_mm` along the plotter's x axis,
// `height_mm` along its y axis. "Sheet coordinates" are millimetres from the sheet corner where the
// plotter's x and y are smallest, along the plotter's +x and +y; plotter (0, 0) sits at
// (origin_x_mm, origin_y_mm) there, so a sheet point s is plotter unit (s − origin) / unit_mm. With
// y_axis_up (HP plotters: y grows away from the user) that corner is the sheet's bottom-left as the
// drawing is seen; otherwise its top-left. The pen reaches [x_min, x_max] × [y_min, y_max] (the hard-clip
// limits); the HPGL device never draws outside that rectangle nor off the sheet.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/device/page/page_layout.hpp"
#include "core/plan/pen_plan.hpp"

namespace hlr {

struct HpglPaperRange {
  // A paper_by_name() name ("A4", "Letter"), matched case-insensitively, or any other name for a custom
  // sheet. A range whose width and height are both 0 accepts a page of any size ("any"): the sheet is then
  // the page itself, as given, and the limits only bound the coordinates (the generic profile).
  std::string paper;
  double width_mm = 0, height_mm = 0;               // the sheet as loaded, along the plotter's x and y axes
  long x_min = 0, x_max = 0, y_min = 0, y_max = 0;  // plotter units, within −32768…32767
  double origin_x_mm = 0, origin_y_mm = 0;          // plotter (0, 0) in sheet coordinates (see above)

  bool any_size() const { return width_mm == 0 && height_mm == 0; }
};

struct HpglProfile {
  std::string name;  // "hp7475a"
  std::string info;  // one line for --help / errors
  double unit_mm = 0.025;
  std::vector<HpglPaperRange> ranges;
  bool y_axis_up = true;    // plotter y grows away from the user (true on HP plotters)
  bool rotate_180 = false;  // the sheet is loaded head first: the page's top lies at the plotter's y_min side
  int pen_count = 8;
  std::optional<double> velocity_cm_s;  // VS, when set (IN leaves HP plotters at their fastest speed)
  bool relative = true;                 // PR moves (smaller files, less buffer load) or PA
  int max_pairs_per_pd = 32;            // cap coordinate pairs per PU/PD (small interpreter buffers)
  bool newline = false;                 // a newline after each command (lp, cheap USB cutters)
  PlotterSpeeds speeds;                 // for the time estimate
};

// hp7475a, hp7440a, hp7550, roland-dxy, generic.
const std::vector<HpglProfile>& builtin_hpgl_profiles();
std::optional<HpglProfile> hpgl_profile_by_name(std::string_view name);  // case-insensitive
std::string hpgl_profile_list();  // "hp7475a, hp7440a, ...", for messages

// Throws DeviceError naming the first problem: a unit that is not finite and positive, no range, a range
// whose limits are empty or leave −32768…32767, a sheet size that is not finite and positive (or 0 × 0),
// fewer than 1 pen, a velocity outside 0.01…1000 cm/s, fewer than 1 pair per PD. The HPGL
// device checks every profile it is given; script-declared profiles can be checked when declared.
void check_hpgl_profile(const HpglProfile& profile);

// "A4 (297 × 210 mm), A3 (420 × 297 mm), …" — the paper sizes a profile accepts, for messages.
std::string hpgl_paper_list(const HpglProfile& profile);

}  // namespace hlr
