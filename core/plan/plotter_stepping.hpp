// Line drawing on an eight-direction incremental plotter (the Newcastle thesis §1.6, procedure `line`;
// reference/004_penup.md §7): every step moves one grid unit along an axis (a "straight" move s) or both
// axes at once (a "diagonal" move d). Direction codes, clockwise from +y:
//   1 = +y, 2 = +x+y, 3 = +x, 4 = +x−y, 5 = −y, 6 = −x−y, 7 = −x, 8 = −x+y.
// A line uses one straight and one diagonal direction. Each step picks the one that keeps the pen closer
// to the true line, measured in integers: δ starts at 0, an s move adds v0 = min(|Δx|, |Δy|), a d move
// subtracts w0 = ||Δx| − |Δy||; take the move with the smaller |δ| after it. Ties are the "Knight's Move
// condition": broken by B = (xB > xA) — d when B, s otherwise — so the steps from B to A are exactly the
// steps from A to B reversed (each direction turned round), and a line drawn twice does not thicken.
#pragma once

#include <string>
#include <string_view>

#include "core/plan/grid_point.hpp"

namespace hlr {

// The direction codes ('1'–'8') from a to b: max(|Δx|, |Δy|) steps, ending exactly at b. With
// `knights_move_correction` false every tie takes the diagonal (the uncorrected procedure).
std::string plotter_steps(GridPoint a, GridPoint b, bool knights_move_correction = true);

// Where the steps lead from `a` (for checks); throws std::invalid_argument on a code outside '1'–'8'.
GridPoint apply_plotter_steps(GridPoint a, std::string_view steps);

// The direction code ('1'–'8') opposite to `code`.
char opposite_plotter_step(char code);

}  // namespace hlr
