// Hidden strokes as the dashes a pen plotter draws. A plotter has no dashed line of its own that every
// model shares, so after planning each hidden stroke is cut, in place, into pen-down dashes with the pen
// lifted over the gaps: the order and direction of the plan are kept, and the pen-up travel added is
// exactly the gaps' length. The pattern is stretched a little on each stroke so that the stroke starts
// and ends with a dash (a hidden corner is always marked); a stroke shorter than one dash and one gap
// is drawn as one dash.
#pragma once

#include "core/plan/pen_plan.hpp"

namespace hlr {

struct DashPattern {
  // Pen-down length and gap as drawn, before stretching. With a 0.3 mm pen (round tip) they are seen as
  // 2.3 mm dashes and 1.2 mm gaps: the cairo devices' look (core/device/page/page_style.hpp).
  double dash_mm = 2;
  double gap_mm = 1.5;
};

// Throws std::invalid_argument when a length is not finite and positive.
void check_dash_pattern(const DashPattern& pattern);

// Cuts every StrokeLayer::Hidden stroke of `plan` into dashes (end points on options.grid_mm, dashes that
// snap to a point dropped) and recomputes the pen-down, pen-up, lift and time figures for what is now
// drawn; stats.hidden_dashes counts the dashes. Visible strokes are untouched.
void dash_hidden_strokes(PenPlan& plan, const DashPattern& pattern, const PlanOptions& options);

}  // namespace hlr
