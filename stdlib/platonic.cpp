// The five Platonic solids. Only the vertices are written down; the faces are recovered as the convex
// hull's facets (every plane through three vertices with all others on one side), which gives exactly
// planar pentagons for the dodecahedron and leaves no face list to get wrong by hand.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "core/tolerance.hpp"
#include "stdlib/generator_detail.hpp"
#include "stdlib/generators.hpp"
#include "stdlib/shapes.hpp"

namespace hlr::stdlib {

using detail::require;

namespace {

constexpr double kPhi = std::numbers::phi;

// Faces of the convex hull of `v` (points in convex position, as all vertices of a Platonic solid are),
// each counter-clockwise about its outward normal. O(n⁴) in the vertex count: at most 20 here.
std::vector<IndexedFace> hull_faces(const std::vector<Point3>& v) {
  double extent = 0;
  for (const Point3& p : v) extent = std::max(extent, length(to_vector(p)));
  const double tol = Tolerance::kRelative * extent;  // on a hull plane: coincidence
  std::set<std::vector<std::uint32_t>> seen;
  std::vector<IndexedFace> faces;
  const auto n = static_cast<std::uint32_t>(v.size());
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j)
      for (std::uint32_t k = j + 1; k < n; ++k) {
        Vector3 normal = normalize(cross(v[j] - v[i], v[k] - v[i]));
        if (length(normal) == 0) continue;
        std::vector<std::uint32_t> on;
        bool above = false, below = false;
        for (std::uint32_t m = 0; m < n; ++m) {
          const double d = dot(normal, v[m] - v[i]);
          if (std::abs(d) <= tol) on.push_back(m);
          above = above || d > tol;
          below = below || d < -tol;
        }
        if (above == below || !seen.insert(on).second) continue;  // not a facet, or found already
        if (above) normal = -normal;
        // Order the facet's vertices by angle about its centre, counter-clockwise about the normal.
        Vector3 c{};
        for (std::uint32_t m : on) c += to_vector(v[m]);
        c = c / static_cast<double>(on.size());
        const Vector3 u = normalize(to_vector(v[on[0]]) - c), w = cross(normal, u);
        auto angle = [&](std::uint32_t m) {
          const Vector3 d = to_vector(v[m]) - c;
          return std::atan2(dot(d, w), dot(d, u));
        };
        std::sort(on.begin(), on.end(),
                  [&](std::uint32_t a, std::uint32_t b) { return angle(a) < angle(b); });
        faces.push_back(IndexedFace{on});
      }
  return faces;
}

Solid platonic(const char* function, double r, std::vector<Point3> unit) {
  require(std::isfinite(r) && r > 0, function, "r must be positive");
  // Scale to circumradius r from the (common) distance of the given vertices to the origin.
  const double scale = r / length(to_vector(unit[0]));
  for (Point3& p : unit) p = to_point(scale * to_vector(p));
  return solid_from_indexed(unit, hull_faces(unit));
}

// All sign combinations of (x, y, z), skipping duplicates from zero components.
std::vector<Point3> signs(double x, double y, double z) {
  std::vector<Point3> p;
  for (int s = 0; s < 8; ++s) {
    const Point3 q{(s & 1) ? -x : x, (s & 2) ? -y : y, (s & 4) ? -z : z};
    if (std::find(p.begin(), p.end(), q) == p.end()) p.push_back(q);
  }
  return p;
}

// The cyclic permutations (x, y, z), (z, x, y), (y, z, x) of every sign combination.
std::vector<Point3> cyclic(double x, double y, double z) {
  std::vector<Point3> p;
  for (const Point3& q : signs(x, y, z)) {
    p.push_back(q);
    p.push_back({q.z, q.x, q.y});
    p.push_back({q.y, q.z, q.x});
  }
  return p;
}

}  // namespace

Solid tetrahedron(double r) {
  return platonic("tetrahedron", r, {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}});
}

Solid hexahedron(double r) { return platonic("hexahedron", r, signs(1, 1, 1)); }

Solid octahedron(double r) { return platonic("octahedron", r, cyclic(1, 0, 0)); }

Solid dodecahedron(double r) {
  std::vector<Point3> v = signs(1, 1, 1);
  for (const Point3& p : cyclic(0, 1 / kPhi, kPhi)) v.push_back(p);
  return platonic("dodecahedron", r, v);
}

Solid icosahedron(double r) { return platonic("icosahedron", r, cyclic(0, 1, kPhi)); }

}  // namespace hlr::stdlib
