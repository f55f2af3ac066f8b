// Even-odd containment in a polygon made of several rings (outer boundary and holes), with an explicit
// boundary band: a point within `tolerance` of any ring edge is on the boundary, neither in nor out.
// The engine treats boundary points as not hidden, so grazing lines stay drawn.
#pragma once

#include <cstdint>
#include <span>

#include "core/geometry/vector.hpp"

namespace hlr {

// Seam: within the tolerance of a seam (an edge the neighbouring face across it covers too), away from its
// ends — covered, unless an exact test says where the point lies.
enum class PointClass { Outside, Boundary, Inside, Seam };

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
// is_seam(i): the edge from points[i] to the next is a seam the polygon shares with a neighbour that
// continues it on the other side, so a point on it (away from its end vertices) is inside the union, not
// on its boundary.
template <typename IsSeam>
PointClass classify_point(std::span<const Point2> points, std::span<const std::uint32_t> ring_ends, Point2 p,
                          double tolerance, IsSeam&& is_seam) {
  const double tol2 = tolerance * tolerance;
  bool inside = false, on_seam = false;
  std::uint32_t begin = 0;
  for (std::uint32_t end : ring_ends) {
    for (std::uint32_t i = begin; i < end; ++i) {
      const Point2 a = points[i];
      const Point2 b = points[i + 1 < end ? i + 1 : begin];
      // Cheap reject first: farther than the tolerance from the edge's line (no division).
      const Vector2 ab = b - a, ap = p - a;
      const double c = cross(ab, ap);
      if (c * c <= tol2 * dot(ab, ab) && distance2_to_segment(p, a, b) <= tol2) {
        // A seam is covered along its length, but at its ends the neighbours around the vertex may be
        // what is being tested: near a vertex the point stays on the boundary.
        if (!is_seam(i) || dot(ap, ap) <= tol2 || dot(p - b, p - b) <= tol2) return PointClass::Boundary;
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
  return on_seam ? PointClass::Seam : (inside ? PointClass::Inside : PointClass::Outside);
}

}  // namespace hlr

namespace hlr {

// Without seams: every ring edge is outline.
inline PointClass classify_point(std::span<const Point2> points, std::span<const std::uint32_t> ring_ends,
                                 Point2 p, double tolerance) {
  return classify_point(points, ring_ends, p, tolerance, [](std::uint32_t) { return false; });
}

}  // namespace hlr
