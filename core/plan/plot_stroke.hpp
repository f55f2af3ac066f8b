// A stroke: what the pen planner produces and every device draws — a polyline in page millimetres
// drawn with one pen without lifting it. It lives with the planner (core/plan/) so that devices depend on
// planning and never the other way round.
#pragma once

#include <vector>

#include "core/geometry/vector.hpp"

namespace hlr {

// Hidden strokes exist only when the hidden layer is on; cairo devices dash them, HPGL gives them their
// own pen (PlotStroke::pen). Hatch strokes are the visible pieces of hatch lines (core/solid/hatching.hpp):
// drawn solid like visible ones, but a layer of their own so that they are planned, and plotted, apart.
enum class StrokeLayer { Visible, Hidden, Hatch };

struct PlotStroke {
  std::vector<Point2> points;  // at least two; consecutive points differ
  int pen = 1;                 // 1-based pen (colour, width; the HPGL `SP` number)
  StrokeLayer layer = StrokeLayer::Visible;
  // Hidden strokes drawn by occlusion level (`style hidden levels N`): how many surfaces hide them, 1..N,
  // each level a layer of its own. 0 for visible strokes and for plain dashed hidden ones.
  int level = 0;
};

}  // namespace hlr
