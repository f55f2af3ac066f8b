#include "core/hlr/smooth_contours.hpp"

#include <algorithm>
#include <cmath>

namespace hlr {
namespace {

const SmallVector<VertexIndex, 4>& outer(const Solid& solid, std::size_t f) {
  return solid.faces[f].rings[0].vertices;
}

}  // namespace

void add_contour_candidates(std::vector<Candidate>& out, std::uint32_t object, const Solid& solid,
                            const CornerNormals& normals, const Camera& camera, std::size_t face_begin,
                            std::size_t face_end) {
  const bool perspective = camera.projection == Projection::Perspective;
  const Point3 eye = perspective ? camera.eye_world() : Point3{};
  const Vector3 direction = camera.direction_world();
  std::vector<double> g;
  for (std::size_t f = face_begin; f < face_end; ++f) {
    const Face& face = solid.faces[f];
    if (face.rings.size() != 1) continue;  // a face with holes keeps its Smooth edges' outline
    const auto& ring = face.rings[0].vertices;
    const std::size_t n = ring.size();
    const std::uint32_t first = normals.first[f];
    g.resize(n);
    bool front = false, back = false;
    for (std::size_t k = 0; k < n; ++k) {
      const Vector3& nk = normals.normals[first + k];
      const Point3 p = solid.vertices[ring[k]];
      g[k] = perspective ? dot(nk, p - eye) : dot(nk, direction);
      (g[k] < 0 ? front : back) = true;
    }
    if (!front || !back) continue;
    // Where g is zero on the side from corner a to corner b: from the corner of the lower vertex index, so
    // that the face across a shared side finds the same point.
    auto zero = [&](std::size_t a, std::size_t b) {
      if (ring[a] > ring[b]) std::swap(a, b);
      const double t = g[a] / (g[a] - g[b]);
      const Point3 pa = solid.vertices[ring[a]], pb = solid.vertices[ring[b]];
      return pa + t * (pb - pa);
    };
    for (std::size_t k = 1; k + 1 < n; ++k) {  // the fan (0, k, k + 1)
      const std::size_t tri[3] = {0, k, k + 1};
      Point3 ends[2];
      int found = 0;
      for (int s = 0; s < 3 && found < 2; ++s) {
        const std::size_t a = tri[s], b = tri[(s + 1) % 3];
        if ((g[a] < 0) != (g[b] < 0)) ends[found++] = zero(a, b);
      }
      if (found < 2 || ends[0] == ends[1]) continue;
      Candidate c;
      c.object = object;
      c.edge = static_cast<std::uint32_t>(f);
      c.source = SegmentSource::Contour;
      c.own_face0 = static_cast<FaceIndex>(f);
      c.view0 = camera.view(ends[0]);
      c.view1 = camera.view(ends[1]);
      out.push_back(c);
    }
  }
}

bool near_contour_face(const Solid& solid, FaceIndex own, FaceIndex other) {
  if (own < 0 || other < 0) return false;
  if (own == other) return true;
  const auto& ring = outer(solid, static_cast<std::size_t>(own));
  const std::size_t n = ring.size();
  Vector3 sum{};
  double longest2 = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Point3 p = solid.vertices[ring[k]];
    sum += to_vector(p);
    const Vector3 side = solid.vertices[ring[(k + 1) % n]] - p;
    longest2 = std::max(longest2, dot(side, side));
  }
  const Point3 centre = Point3{} + (1.0 / static_cast<double>(n)) * sum;
  const double reach2 = longest2;
  for (const VertexIndex v : outer(solid, static_cast<std::size_t>(other))) {
    const Vector3 d = solid.vertices[v] - centre;
    if (dot(d, d) <= reach2) return true;
  }
  return false;
}

}  // namespace hlr
