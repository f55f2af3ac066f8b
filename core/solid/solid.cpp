#include "core/solid/solid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "core/solid/face_geometry.hpp"

namespace hlr {

Vector3 newell_normal(const std::vector<Point3>& vertices, std::span<const VertexIndex> r) {
  if (r.size() < 3) return {};
  // Newell's sums over coordinates relative to the first vertex: the same vector, without the
  // cancellation that large absolute coordinates would cause.
  const Point3 o = vertices[r[0]];
  Vector3 n{};
  Vector3 a{};  // vertex i − o; the first is zero
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Vector3 b = i + 1 < r.size() ? vertices[r[i + 1]] - o : Vector3{};
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
    a = b;
  }
  return n;
}

void link_ring_edges(Solid& solid) {
  std::unordered_map<std::uint64_t, std::uint32_t> index;
  index.reserve(solid.edges.size() * 2);
  auto key = [](VertexIndex a, VertexIndex b) {
    return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
  };
  for (std::uint32_t e = 0; e < solid.edges.size(); ++e)
    if (solid.edges[e].kind != EdgeKind::Marking && solid.edges[e].kind != EdgeKind::Free &&
        solid.edges[e].kind != EdgeKind::Hatch)
      index.emplace(key(solid.edges[e].v0, solid.edges[e].v1), e);
  for (Face& f : solid.faces)
    for (Ring& r : f.rings) {
      const std::size_t n = r.vertices.size();
      r.edges.assign(n, kNoEdge);
      for (std::size_t i = 0; i < n; ++i) {
        const auto it = index.find(key(r.vertices[i], r.vertices[(i + 1) % n]));
        if (it != index.end()) r.edges[i] = it->second;
      }
    }
}

Solid Solid::transformed(const Affine3& worldFromObject) const {
  const double det = worldFromObject.determinant();
  if (det == 0 || !std::isfinite(det))
    throw std::domain_error("transform is singular: it would flatten the solid");

  Solid out;
  out.closed = closed;
  out.folded = folded;
  out.crease_angle_deg = crease_angle_deg;
  out.smooth_contours = smooth_contours;
  out.hatch_pen = hatch_pen;
  out.vertices.reserve(vertices.size());
  for (const Point3& p : vertices) out.vertices.push_back(worldFromObject.apply(p));

  // A mirror reverses every ring as seen from outside: reverse them back so outer rings stay
  // counter-clockwise and normals outward, and swap the sides of the edges to match.
  const bool mirror = det < 0;
  out.faces = faces;
  if (mirror)
    for (Face& f : out.faces)
      for (Ring& r : f.rings) {
        // Reversed, edge j joins old vertices n−1−j and n−2−j: old edge (n−2−j) mod n.
        std::reverse(r.vertices.begin(), r.vertices.end());
        const SmallVector<std::uint32_t, 4> old = r.edges;
        const std::size_t n = old.size();
        for (std::size_t j = 0; j < n; ++j) r.edges[j] = old[(2 * n - 2 - j) % n];
      }

  out.planes.reserve(out.faces.size());
  for (const Face& f : out.faces)
    out.planes.push_back(f.rings.empty() ? Plane{} : solid_detail::newell_plane(out.vertices, f.rings[0]));

  out.edges = edges;
  for (SolidEdge& e : out.edges) {
    if (mirror && e.left != e.right) {
      // Two faces: swap sides. One face (boundary): keep it on the left by reversing the edge instead.
      if (e.right == kNoFace)
        std::swap(e.v0, e.v1);
      else
        std::swap(e.left, e.right);
    }
    // Coplanarity and concavity survive any affine map; dihedral angles do not (non-uniform scaling),
    // so re-decide Smooth against Feature with the new planes. Flat stays Flat: those faces were judged
    // coplanar in object space, and a stretch must not make rounding noise visible.
    if (e.kind == EdgeKind::Feature || e.kind == EdgeKind::Smooth) {
      const Vector3 dir = out.vertices[e.v1] - out.vertices[e.v0];
      e.kind = solid_detail::classify_dihedral(dir, out.planes[e.left].normal, out.planes[e.right].normal,
                                               crease_angle_deg)
                   .kind;
      // Squashed nearly flat by an extreme stretch, but not coplanar: below any positive crease angle.
      if (e.kind == EdgeKind::Flat) e.kind = crease_angle_deg > 0 ? EdgeKind::Smooth : EdgeKind::Feature;
    }
  }
  return out;
}

}  // namespace hlr
