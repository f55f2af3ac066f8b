// Triangulation of the non-planar polygons found in mesh files. The polygon is projected onto the plane
// of its Newell normal, where a fan serves strictly convex outlines and ear clipping the rest. The
// result keeps the polygon's winding, so consistent input stays consistent.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/tolerance.hpp"
#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib::mesh_detail {

namespace {

// Whether p lies inside or on the counter-clockwise triangle abc.
bool inside_or_on(Point2 p, Point2 a, Point2 b, Point2 c) {
  return cross(b - a, p - a) >= 0 && cross(c - b, p - b) >= 0 && cross(a - c, p - c) >= 0;
}

}  // namespace

bool triangulate(const std::vector<Point3>& points, const std::vector<std::uint32_t>& ring, Vector3 normal,
                 std::vector<Triangle>& out, std::int64_t& budget) {
  const std::size_t n = ring.size();
  if (n < 3) return true;
  if (n == 3) {
    out.push_back({ring[0], ring[1], ring[2]});
    return true;
  }

  // Frame (u, v) with u × v along the normal: the ring is counter-clockwise in it.
  const Vector3 w = normalize(normal);
  const double ax = std::abs(w.x), ay = std::abs(w.y), az = std::abs(w.z);
  const Vector3 axis =
      (ax <= ay && ax <= az) ? Vector3{1, 0, 0} : (ay <= az ? Vector3{0, 1, 0} : Vector3{0, 0, 1});
  const Vector3 u = normalize(cross(w, axis)), v = cross(w, u);
  const Point3 origin = points[ring[0]];
  std::vector<Point2> p(n);
  double lo_x = 0, hi_x = 0, lo_y = 0, hi_y = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vector3 d = points[ring[i]] - origin;
    p[i] = {dot(d, u), dot(d, v)};
    lo_x = std::min(lo_x, p[i].x), hi_x = std::max(hi_x, p[i].x);
    lo_y = std::min(lo_y, p[i].y), hi_y = std::max(hi_y, p[i].y);
  }
  const double size2 = (hi_x - lo_x) * (hi_x - lo_x) + (hi_y - lo_y) * (hi_y - lo_y);
  const double eps = Tolerance::kRelative * size2;  // twice a triangle area below this is degenerate
  auto turn = [&](std::size_t a, std::size_t b, std::size_t c) { return cross(p[b] - p[a], p[c] - p[b]); };

  // Strictly convex (every turn left, turning once around): a fan from the first vertex.
  budget -= static_cast<std::int64_t>(n);
  if (budget < 0) return false;
  bool convex = true;
  double turning = 0;
  for (std::size_t i = 0; i < n && convex; ++i) {
    const std::size_t a = (i + n - 1) % n, c = (i + 1) % n;
    const double t = turn(a, i, c);
    convex = t > eps;
    turning += std::atan2(t, dot(p[i] - p[a], p[c] - p[i]));
  }
  if (convex && std::abs(turning - 2 * std::numbers::pi) < Tolerance::kTurning) {
    for (std::size_t i = 1; i + 1 < n; ++i) out.push_back({ring[0], ring[i], ring[i + 1]});
    return true;
  }

  // Ear clipping over a circular doubly linked list of the remaining vertices.
  std::vector<std::size_t> prev(n), next(n);
  for (std::size_t i = 0; i < n; ++i) {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  std::size_t remaining = n, i = 0, misses = 0;
  auto is_ear = [&](std::size_t b) {
    const std::size_t a = prev[b], c = next[b];
    if (turn(a, b, c) <= eps) return false;
    for (std::size_t k = next[c]; k != a; k = next[k]) {
      const Point2 q = p[k];
      if (q == p[a] || q == p[b] || q == p[c]) continue;  // a vertex repeated by position only
      if (inside_or_on(q, p[a], p[b], p[c])) return false;
    }
    return true;
  };
  auto clip = [&](std::size_t b) {
    out.push_back({ring[prev[b]], ring[b], ring[next[b]]});
    next[prev[b]] = next[b];
    prev[next[b]] = prev[b];
    --remaining;
    misses = 0;
    return next[b];
  };
  while (remaining > 3) {
    budget -= static_cast<std::int64_t>(remaining);
    if (budget < 0) {
      out.clear();
      return false;
    }
    if (is_ear(i)) {
      i = clip(i);
      continue;
    }
    i = next[i];
    if (++misses < remaining) continue;
    // No ear: the projection overlaps itself. Clip the most convex vertex so the loop always ends.
    std::size_t best = i;
    for (std::size_t k = next[i]; k != i; k = next[k])
      if (turn(prev[k], k, next[k]) > turn(prev[best], best, next[best])) best = k;
    i = clip(best);
  }
  out.push_back({ring[prev[i]], ring[i], ring[next[i]]});
  return true;
}

}  // namespace hlr::stdlib::mesh_detail
