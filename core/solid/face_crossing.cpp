#include "core/solid/face_crossing.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry/exact_crossing.hpp"
#include "core/geometry/exact_predicates.hpp"
#include "core/geometry/polygon2d.hpp"
#include "core/tolerance.hpp"

namespace hlr {
namespace {

// A point of the face's plane in 2-D, dropping the normal's dominant axis (an affine view of the plane,
// so containment is unchanged).
Point2 flatten(Point3 p, int drop) {
  if (drop == 0) return {p.y, p.z};
  if (drop == 1) return {p.z, p.x};
  return {p.x, p.y};
}

// Parameter intervals of the line origin + λ·dir lying strictly inside face f of `solid`, whose plane
// `other_plane` crosses.
void inside_intervals(const Solid& solid, FaceIndex f, const Plane& other_plane, Point3 origin, Vector3 dir,
                      double tol, FaceCrossingScratch& s, std::vector<std::pair<double, double>>& out) {
  out.clear();
  std::vector<double>& breaks = s.breaks;
  breaks.clear();
  auto param = [&](Point3 x) { return dot(x - origin, dir); };
  for (const Ring& ring : solid.faces[f].rings) {
    const std::size_t n = ring.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point3 p = solid.vertices[ring.vertices[i]], q = solid.vertices[ring.vertices[(i + 1) % n]];
      const double dp = other_plane.signed_distance(p), dq = other_plane.signed_distance(q);
      if ((dp > tol && dq > tol) || (dp < -tol && dq < -tol)) continue;
      if (std::abs(dp) <= tol) breaks.push_back(param(p));
      if (std::abs(dq) <= tol) breaks.push_back(param(q));
      if ((dp > tol && dq < -tol) || (dp < -tol && dq > tol))
        breaks.push_back(param(lerp(p, q, dp / (dp - dq))));
    }
  }
  if (breaks.size() < 2) return;
  std::sort(breaks.begin(), breaks.end());
  const Vector3 n = solid.planes[f].normal;
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  const int drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
  s.points.clear();
  s.ring_ends.clear();
  for (const Ring& ring : solid.faces[f].rings) {
    for (VertexIndex v : ring.vertices) s.points.push_back(flatten(solid.vertices[v], drop));
    s.ring_ends.push_back(static_cast<std::uint32_t>(s.points.size()));
  }
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = breaks[i], b = breaks[i + 1];
    if (b - a <= tol) continue;
    const Point2 mid = flatten(origin + (0.5 * (a + b)) * dir, drop);
    if (classify_point(s.points, s.ring_ends, mid, tol) != PointClass::Inside) continue;
    if (!out.empty() && out.back().second >= a) {
      out.back().second = b;
    } else {
      out.emplace_back(a, b);
    }
  }
}

bool is_triangle(const Solid& s, FaceIndex f) {
  return s.faces[f].rings.size() == 1 && s.faces[f].rings[0].vertices.size() == 3;
}

}  // namespace

bool face_meets_plane(const Solid& s, FaceIndex f, const Plane& plane, double tol) {
  bool above = false, below = false;
  for (VertexIndex v : s.faces[f].rings[0].vertices) {
    const double d = plane.signed_distance(s.vertices[v]);
    if (d <= tol) below = true;
    if (d >= -tol) above = true;
    if (above && below) return true;
  }
  return false;
}

void face_crossings(const Solid& sa, FaceIndex fa, const Solid& sb, FaceIndex fb, double tol,
                    FaceCrossingScratch& scratch, std::vector<CrossingPiece>& out) {
  const Plane& pa = sa.planes[fa];
  const Plane& pb = sb.planes[fb];
  Vector3 dir = cross(pa.normal, pb.normal);
  const double d2 = dot(dir, dir);
  if (std::sqrt(d2) < Tolerance::kExactCrossingAngle && is_triangle(sa, fa) && is_triangle(sb, fb)) {
    // Planes at a grazing angle: where they cross, exactly — unless each lies within the tolerance of the
    // other (coplanar but for rounding: a flat region's triangles, which have no line).
    const auto& ra = sa.faces[fa].rings[0].vertices;
    const auto& rb = sb.faces[fb].rings[0].vertices;
    auto within = [&](const Solid& s, const auto& ring, const Plane& plane) {
      return std::all_of(ring.begin(), ring.end(), [&](VertexIndex v) {
        return std::abs(plane.signed_distance(s.vertices[v])) <= tol;
      });
    };
    if (within(sa, ra, pb) && within(sb, rb, pa)) return;
    const Triangle3 ta{sa.vertices[ra[0]], sa.vertices[ra[1]], sa.vertices[ra[2]]};
    const Triangle3 tb{sb.vertices[rb[0]], sb.vertices[rb[1]], sb.vertices[rb[2]]};
    // Most such pairs lie wholly to one side of each other, which the filtered predicates tell cheaply.
    auto apart = [](const Triangle3& t, const Triangle3& u) {
      const int s0 = orient3d(t[0], t[1], t[2], u[0]);
      return s0 != 0 && s0 == orient3d(t[0], t[1], t[2], u[1]) && s0 == orient3d(t[0], t[1], t[2], u[2]);
    };
    if (apart(ta, tb) || apart(tb, ta)) return;
    const auto x = exact_triangle_crossing(ta, tb);
    if (x && distance((*x)[0], (*x)[1]) > tol) out.push_back({(*x)[0], (*x)[1]});
    return;
  }
  if (std::sqrt(d2) < Tolerance::kCoplanarAngle) return;  // parallel or coplanar: no line
  // A point on both planes (n·x = −offset): x0 = (h1 (n2 × d) + h2 (d × n1)) / |d|².
  const Point3 origin =
      to_point(((-pa.offset) * cross(pb.normal, dir) + (-pb.offset) * cross(dir, pa.normal)) / d2);
  dir = dir / std::sqrt(d2);
  inside_intervals(sa, fa, pb, origin, dir, tol, scratch, scratch.in_a);
  if (scratch.in_a.empty()) return;
  inside_intervals(sb, fb, pa, origin, dir, tol, scratch, scratch.in_b);
  for (const auto& [xlo, xhi] : scratch.in_a)
    for (const auto& [ylo, yhi] : scratch.in_b) {
      const double lo = std::max(xlo, ylo), hi = std::min(xhi, yhi);
      if (hi - lo <= tol) continue;
      out.push_back({origin + lo * dir, origin + hi * dir});
    }
}

}  // namespace hlr
