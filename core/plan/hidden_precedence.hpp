// Visible lines take precedence over hidden ones, as in every technical drawing: where a hidden piece lies
// on a visible one on the page — the bottom edge of a box behind its top edge in a plan view — only the
// visible line is drawn, by occlusion level a deeper piece gives way to a shallower one, and hidden lines
// on one another are drawn once. Without this
// a plotter draws the line twice (dashed over solid) and a PDF shows dashes over the outline. The engine's
// pieces are not changed (JSON still lists them); only the pieces planned are.
#pragma once

#include <vector>

#include "core/plan/pen_plan.hpp"

namespace hlr {

// Cuts out of every Hidden piece the parts within Tolerance::kCoincidentLineMm of a Visible piece on the
// same line (lines that coincide on the page; see the .cpp for pieces at a slant within the tolerance), of a Hidden piece of a lower level, or of an earlier Hidden piece of its own level (the back
// and front edges of a hole seen end on: one dashed line); what remains of it (one or more pieces, each
// longer than the tolerance) keeps its place in the order. Hatch pieces neither cover nor are covered.
// Returns how many hidden pieces were cut or removed.
std::size_t drop_hidden_under_visible(std::vector<PlotPiece>& pieces);

}  // namespace hlr
