// Corner normals (solid.hpp, CornerNormals): the normals of the smooth surface a mesh stands for.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/solid/solid.hpp"

namespace hlr {
namespace {

// Position of vertex v in face f's outer ring, or −1.
int corner_of(const Solid& solid, FaceIndex f, VertexIndex v) {
  const auto& ring = solid.faces[static_cast<std::size_t>(f)].rings[0].vertices;
  for (std::size_t k = 0; k < ring.size(); ++k)
    if (ring[k] == v) return static_cast<int>(k);
  return -1;
}

std::uint32_t find(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

CornerNormals compute_corner_normals(const Solid& solid) {
  CornerNormals out;
  const std::size_t nf = solid.faces.size();
  out.first.resize(nf + 1, 0);
  for (std::size_t f = 0; f < nf; ++f)
    out.first[f + 1] =
        out.first[f] + static_cast<std::uint32_t>(
                           solid.faces[f].rings.empty() ? 0 : solid.faces[f].rings[0].vertices.size());
  const std::uint32_t corners = out.first[nf];
  // Corners round one vertex joined across smooth and flat edges share their normal.
  std::vector<std::uint32_t> parent(corners);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const SolidEdge& e : solid.edges) {
    if ((e.kind != EdgeKind::Smooth && e.kind != EdgeKind::Flat) || e.left < 0 || e.right < 0) continue;
    for (const VertexIndex v : {e.v0, e.v1}) {
      const int a = corner_of(solid, e.left, v), b = corner_of(solid, e.right, v);
      if (a < 0 || b < 0) continue;  // on a hole's ring
      const std::uint32_t ra =
          find(parent, out.first[static_cast<std::size_t>(e.left)] + static_cast<std::uint32_t>(a));
      const std::uint32_t rb =
          find(parent, out.first[static_cast<std::size_t>(e.right)] + static_cast<std::uint32_t>(b));
      if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
    }
  }
  // Each face's normal weighted by its angle at the corner: the mean does not depend on how the
  // surface round the vertex was cut into triangles.
  std::vector<Vector3> sum(corners, Vector3{});
  for (std::size_t f = 0; f < nf; ++f) {
    if (solid.faces[f].rings.empty()) continue;
    const auto& ring = solid.faces[f].rings[0].vertices;
    const std::size_t n = ring.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Point3 p = solid.vertices[ring[k]];
      const Vector3 u = solid.vertices[ring[(k + n - 1) % n]] - p, w = solid.vertices[ring[(k + 1) % n]] - p;
      const double angle = std::atan2(length(cross(u, w)), dot(u, w));
      sum[find(parent, out.first[f] + static_cast<std::uint32_t>(k))] += angle * solid.planes[f].normal;
    }
  }
  out.normals.resize(corners);
  for (std::size_t f = 0; f < nf; ++f)
    for (std::uint32_t c = out.first[f]; c < out.first[f + 1]; ++c) {
      const Vector3 s = sum[find(parent, c)];
      const double len = length(s);
      // A vertex whose faces' normals cancel (a fold): its own face's normal.
      out.normals[c] = len > 0 ? (1 / len) * s : solid.planes[f].normal;
    }
  return out;
}

}  // namespace

const CornerNormals& Solid::corner_normals() const {
  return corner_normal_cache.get([this] { return compute_corner_normals(*this); });
}

}  // namespace hlr
