// Clipping a 2-D segment to an axis-aligned rectangle (Liang–Barsky): the parameter range of
// a + s·(b − a) that lies inside, or nothing.
#pragma once

#include <optional>
#include <utility>

#include "core/geometry/rect2.hpp"
#include "core/geometry/vector.hpp"

namespace hlr {

inline std::optional<std::pair<double, double>> clip_segment_to_rect(Point2 a, Point2 b, const Rect2& r) {
  double s0 = 0, s1 = 1;
  const double dx = b.x - a.x, dy = b.y - a.y;
  // Each boundary as p·s ≤ q.
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - r.xmin, r.xmax - a.x, a.y - r.ymin, r.ymax - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return std::nullopt;
      continue;
    }
    const double s = q[i] / p[i];
    if (p[i] < 0) {
      if (s > s1) return std::nullopt;
      if (s > s0) s0 = s;
    } else {
      if (s < s0) return std::nullopt;
      if (s < s1) s1 = s;
    }
  }
  return std::make_pair(s0, s1);
}

}  // namespace hlr
