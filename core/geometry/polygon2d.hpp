// Even-odd containment in a polygon made of several rings (outer boundary and holes), with an explicit
// boundary band: a point within `tolerance` of any ring edge is on the boundary, neither in nor out.
// The engine treats boundary points as not hidden, so grazing lines stay drawn.
#pragma once

#include <cstdint>
#include <span>

#include "core/geometry/vector.hpp"

namespace hlr {

enum class PointClass { Outside, Boundary, Inside };

// Squared distance from p to the segment a–b.
inline double distance2_to_segment(Point2 p, Point2 a, Point2 b) {
  const Vector2 ab = b - a, ap = p - a;
  const double len2 = dot(ab, ab);
  double t = len2 > 0 ? dot(ap, ab) / len2 : 0;
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  const Vector2 d = p - lerp(a, b, t);
  return dot(d, d);
}

// points: all rings concatenated; ring_ends: exclusive end offset of each ring within `points`.
// seam (optional, one flag per point): the edge from points[i] to the next is a seam the polygon shares
// with a neighbour that continues it on the other side, so a point on it is inside the union, not on its
// boundary.
inline PointClass classify_point(std::span<const Point2> points, std::span<const std::uint32_t> ring_ends,
                                 Point2 p, double tolerance, std::span<const std::uint8_t> seam = {}) {
  const double tol2 = tolerance * tolerance;
  bool inside = false, on_seam = false;
  std::uint32_t begin = 0;
  for (std::uint32_t end : ring_ends) {
    for (std::uint32_t i = begin; i < end; ++i) {
      const Point2 a = points[i];
      const Point2 b = points[i + 1 < end ? i + 1 : begin];
      if (distance2_to_segment(p, a, b) <= tol2) {
        if (seam.empty() || !seam[i]) return PointClass::Boundary;
        on_seam = true;
      }
      // Half-open rule on y so a vertex on the ray is counted once.
      if ((a.y > p.y) != (b.y > p.y)) {
        const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
        if (x > p.x) inside = !inside;
      }
    }
    begin = end;
  }
  return (inside || on_seam) ? PointClass::Inside : PointClass::Outside;
}

}  // namespace hlr
