// Clipping a 2-D segment to an axis-aligned rectangle (Liang–Barsky): the parameter range of
// a + s·(b − a) that lies inside, or nothing.
#pragma once

#include <optional>
#include <utility>
#include <vector>

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

// A polyline clipped to `r`, as the pieces that lie inside: move_to(p) starts a piece, line_to(p)
// continues it. A polyline leaving and re-entering the rectangle becomes several pieces; a single point
// inside is a piece of one point (move_to, line_to at the same place: a dot with round caps).
template <typename MoveTo, typename LineTo>
void clip_polyline_to_rect(const std::vector<Point2>& pts, const Rect2& r, MoveTo&& move_to, LineTo&& line_to) {
  if (pts.empty()) return;
  if (pts.size() == 1) {
    if (!r.contains(pts[0])) return;
    move_to(pts[0]);
    line_to(pts[0]);
    return;
  }
  bool drawing = false;  // the current piece ends at the end of the previous (clipped) segment
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const Point2 a0 = pts[i - 1], b0 = pts[i];
    const auto range = clip_segment_to_rect(a0, b0, r);
    if (!range || range->first >= range->second) {  // outside, or touching the rectangle at one point
      drawing = false;
      continue;
    }
    const double dx = b0.x - a0.x, dy = b0.y - a0.y;
    const Point2 a = range->first > 0 ? Point2{a0.x + range->first * dx, a0.y + range->first * dy} : a0;
    const Point2 b = range->second < 1 ? Point2{a0.x + range->second * dx, a0.y + range->second * dy} : b0;
    if (!drawing || range->first > 0) move_to(a);
    line_to(b);
    drawing = range->second >= 1;
  }
}

}  // namespace hlr
