#include "tests/support/mesh_views.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/solid/solid_builder.hpp"
#include "stdlib/generators.hpp"
#include "stdlib/mesh_detail.hpp"

namespace hlr::test {

Solid mesh_solid(const std::vector<Point3>& vertices, const std::vector<std::vector<VertexIndex>>& faces,
                 double crease_angle_deg) {
  SolidBuildOptions options;
  options.crease_angle_deg = crease_angle_deg;
  SolidBuilder builder(options);
  std::vector<VertexIndex> index;
  for (Point3 p : vertices) index.push_back(builder.add_vertex(p));
  for (const auto& face : faces) {
    std::vector<VertexIndex> loop;
    for (VertexIndex v : face) loop.push_back(index[v]);
    builder.add_indexed_face_loop(loop);
  }
  SolidBuildResult built = builder.build();
  if (!built.ok()) {
    std::string why;
    for (const auto& d : built.diagnostics) why += d.message + "\n";
    ADD_FAILURE() << "the mesh does not build:\n" << why;
    return stdlib::box({0, 0, 0}, {1, 1, 1});
  }
  return std::move(*built.solid);
}

std::vector<std::vector<VertexIndex>> triangles_of(const Solid& s) {
  std::vector<std::vector<VertexIndex>> faces;
  std::vector<stdlib::mesh_detail::Triangle> triangles;
  std::int64_t budget = 1 << 30;
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    if (s.faces[f].rings.size() != 1) ADD_FAILURE() << "triangles_of: face " << f << " has holes";
    const auto& ring = s.faces[f].rings[0].vertices;
    // Ear clipping, as the importer does: a fan of a concave face would overlap itself.
    triangles.clear();
    const std::vector<std::uint32_t> loop(ring.begin(), ring.end());
    if (!stdlib::mesh_detail::triangulate(s.vertices, loop, s.planes[f].normal, triangles, budget))
      ADD_FAILURE() << "triangles_of: face " << f << " does not triangulate";
    for (const auto& t : triangles) faces.push_back({t[0], t[1], t[2]});
  }
  return faces;
}

Camera random_view(Rng& r, Point3 center, double size, int n) {
  const Point3 eye = center + r(3, 5) * size * r.direction();
  const Vector3 up = std::abs(normalize(center - eye).z) > 0.99 ? Vector3{0, 1, 0} : Vector3{0, 0, 1};
  if (n % 3 == 2) return ortho_camera(OrthoParameters{eye, center, up, 2.5 * size, 0});
  return lookat_camera(LookatParameters{eye, center, up, r(30, 60), 0, 0});
}

}  // namespace hlr::test
