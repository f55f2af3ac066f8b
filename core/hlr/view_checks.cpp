#include "core/hlr/view_checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/geometry/box3.hpp"
#include "core/tolerance.hpp"

namespace hlr {
namespace {

// Directions no face of a generated solid is likely to contain: tried in turn while a ray grazes.
constexpr std::array<Vector3, 4> kRays{{{0.5773502, 0.5773503, 0.5773504},
                                        {-0.3141593, 0.7071068, 0.6339746},
                                        {0.8017837, -0.2672612, 0.5345225},
                                        {-0.4082483, -0.4082482, -0.8164966}}};

enum class Crossing { None, Through, Grazes };

// Whether the ray p + t·d (t > 0) crosses face f of `solid` inside its polygon (holes excluded).
Crossing ray_crosses_face(const Solid& solid, std::size_t f, Point3 p, Vector3 d, double tolerance) {
  const Plane& plane = solid.planes[f];
  const double along = dot(plane.normal, d);
  const double from = plane.signed_distance(p);
  if (std::abs(along) <= Tolerance::kRelative)
    return std::abs(from) <= tolerance ? Crossing::Grazes : Crossing::None;
  const double t = -from / along;
  if (t <= 0) return Crossing::None;
  const Point3 q = p + t * d;
  // Drop the normal's largest axis and test q in the face's polygon, even-odd over every ring.
  const Vector3 n = plane.normal;
  const int drop = std::abs(n.x) >= std::abs(n.y) && std::abs(n.x) >= std::abs(n.z) ? 0
                   : std::abs(n.y) >= std::abs(n.z)                                 ? 1
                                                                                    : 2;
  const auto flat = [drop](Point3 v) {
    return drop == 0 ? Point2{v.y, v.z} : drop == 1 ? Point2{v.x, v.z} : Point2{v.x, v.y};
  };
  const Point2 a = flat(q);
  bool inside = false;
  for (const Ring& ring : solid.faces[f].rings) {
    const std::size_t n_vertices = ring.vertices.size();
    for (std::size_t i = 0, j = n_vertices - 1; i < n_vertices; j = i++) {
      const Point2 u = flat(solid.vertices[ring.vertices[i]]), v = flat(solid.vertices[ring.vertices[j]]);
      // Distance from the crossing point to this edge: within the tolerance, the ray grazes it.
      const Vector2 e{v.x - u.x, v.y - u.y}, w{a.x - u.x, a.y - u.y};
      const double len2 = e.x * e.x + e.y * e.y;
      const double s = len2 > 0 ? std::clamp((w.x * e.x + w.y * e.y) / len2, 0.0, 1.0) : 0.0;
      if (std::hypot(w.x - s * e.x, w.y - s * e.y) <= tolerance) return Crossing::Grazes;
      if ((u.y > a.y) != (v.y > a.y) && a.x < u.x + (a.y - u.y) * (v.x - u.x) / (v.y - u.y)) inside = !inside;
    }
  }
  return inside ? Crossing::Through : Crossing::None;
}

}  // namespace

bool point_inside_closed_solid(const Solid& solid, Point3 p) {
  if (!solid.closed || solid.vertices.empty()) return false;
  Box3 box;
  for (const Point3& v : solid.vertices) box.include(v);
  const Point3 lo = box.lo, hi = box.hi;
  if (p.x < lo.x || p.y < lo.y || p.z < lo.z || p.x > hi.x || p.y > hi.y || p.z > hi.z) return false;
  const double tolerance = Tolerance::kRelative * std::max(distance(lo, hi), 1.0);
  for (const Vector3& d : kRays) {
    bool ambiguous = false;
    std::size_t crossings = 0;
    for (std::size_t f = 0; f < solid.faces.size() && !ambiguous; ++f) {
      const Crossing c = ray_crosses_face(solid, f, p, d, tolerance);
      ambiguous = c == Crossing::Grazes;
      crossings += c == Crossing::Through;
    }
    if (!ambiguous) return crossings % 2 == 1;
  }
  return false;  // every ray grazed: on the surface, or too close to call
}

ViewProblems check_view(const Scene& scene, const Camera& camera) {
  ViewProblems out;
  const bool perspective = camera.projection == Projection::Perspective;
  if (perspective) {
    const Point3 eye = camera.eye_world();
    for (std::size_t i = 0; i < scene.objects.size() && !out.eye_inside; ++i)
      if (point_inside_closed_solid(*scene.objects[i].solid, eye)) out.eye_inside = i;
    for (const SceneObject& o : scene.objects)
      for (const Point3& v : o.solid->vertices) {
        const double depth = camera.view(v).z;
        if (!(depth > 0)) continue;
        ++out.vertices_in_front;
        out.vertices_cut_away += depth < camera.near_depth;
      }
  }
  return out;
}

}  // namespace hlr
