// Integer points on the device grid (plotter units): the vertex keys of the pen planner and the end points
// of the incremental plotter's steps.
#pragma once

#include <cstdint>

namespace hlr {

struct GridPoint {
  std::int64_t x = 0, y = 0;
  friend constexpr bool operator==(GridPoint a, GridPoint b) { return a.x == b.x && a.y == b.y; }
};

}  // namespace hlr
