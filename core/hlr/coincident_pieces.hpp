// Pieces drawn twice: where solids share an edge line (identical parts stacked, a box flush against
// another), several visible pieces lie on one another. The plotter draws such a line once; the engine's
// result says so too, so JSON and other consumers of the segments see the drawing that is plotted.
#pragma once

#include <vector>

#include "core/hlr/visible_segment.hpp"

namespace hlr {

// Removes every visible piece that earlier visible pieces (in result order) lying on the same line
// cover wholly, in the world and on the picture alike (within the tolerance of the coordinates).
// Pieces only partly covered are kept whole; hidden pieces are left as they are. Returns how many were
// removed. The order of what remains is unchanged and each piece is decided on its own, so the result
// does not depend on `threads` (as core/parallel.hpp's parallel_chunks takes it).
std::size_t remove_covered_pieces(std::vector<VisibleSegment>& segments, unsigned threads = 0);

}  // namespace hlr
