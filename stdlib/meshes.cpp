// Meshes of curved surfaces: UV sphere, torus and the bumpy closed triangle mesh used by benchmarks.
// Faces are listed in a fixed order and then oriented outward against a known outward direction, which
// is simpler and safer than reasoning about each winding by hand.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include "stdlib/generator_detail.hpp"
#include "stdlib/generators.hpp"

namespace hlr::stdlib {

using detail::require;

namespace {

constexpr double kPi = std::numbers::pi;

Point3 centroid(const std::vector<Point3>& v, const std::vector<std::uint32_t>& ring) {
  Vector3 s{};
  for (std::uint32_t i : ring) s += to_vector(v[i]);
  return to_point(s / static_cast<double>(ring.size()));
}

// Deterministic hash → [−1, 1] (splitmix64), so a mesh is identical on every platform for a given seed.
double hash_unit(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ULL + index + 0x632BE59BD9B4E019ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / static_cast<double>(1ULL << 52) - 1.0;
}

// A UV grid on the unit sphere: vertex 0 the north pole, rings 1..stacks−1 of `slices` vertices, then the
// south pole. Faces are polar triangles and quads (or two triangles each when `triangulate`).
struct UvGrid {
  int slices, stacks;
  std::uint32_t ring(int i, int j) const {
    return static_cast<std::uint32_t>(1 + (i - 1) * slices + ((j % slices) + slices) % slices);
  }
  std::uint32_t south() const { return static_cast<std::uint32_t>(1 + (stacks - 1) * slices); }
  std::uint32_t vertex_count() const { return south() + 1; }
  Vector3 direction(std::uint32_t index) const {
    if (index == 0) return {0, 0, 1};
    if (index == south()) return {0, 0, -1};
    const int i = 1 + static_cast<int>(index - 1) / slices, j = static_cast<int>(index - 1) % slices;
    const double theta = kPi * i / stacks, phi = 2 * kPi * j / slices;
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
  }
  std::vector<IndexedFace> faces(bool triangulate) const {
    std::vector<IndexedFace> f;
    for (int j = 0; j < slices; ++j) f.push_back({{0, ring(1, j), ring(1, j + 1)}});
    for (int i = 1; i + 1 < stacks; ++i)
      for (int j = 0; j < slices; ++j) {
        const std::uint32_t a = ring(i, j), b = ring(i + 1, j), c = ring(i + 1, j + 1), d = ring(i, j + 1);
        if (!triangulate) {
          f.push_back({{a, b, c, d}});
        } else if ((i + j) % 2 == 0) {  // alternate the diagonal so the mesh has no preferred direction
          f.push_back({{a, b, c}});
          f.push_back({{a, c, d}});
        } else {
          f.push_back({{a, b, d}});
          f.push_back({{b, c, d}});
        }
      }
    for (int j = 0; j < slices; ++j) f.push_back({{south(), ring(stacks - 1, j + 1), ring(stacks - 1, j)}});
    return f;
  }
};

}  // namespace

Solid sphere(Point3 center, double radius, int slices, int stacks, double crease_angle_deg) {
  require(slices >= 3, "sphere", "needs at least 3 slices");
  require(stacks >= 2, "sphere", "needs at least 2 stacks");
  require(radius > 0 && std::isfinite(radius), "sphere", "radius must be positive");
  const UvGrid grid{slices, stacks};
  std::vector<Point3> v(grid.vertex_count());
  for (std::uint32_t i = 0; i < v.size(); ++i) v[i] = center + radius * grid.direction(i);
  std::vector<IndexedFace> faces = grid.faces(false);
  for (auto& f : faces) detail::orient_face(v, f, centroid(v, f[0]) - center);
  return solid_from_indexed(v, faces, crease_angle_deg);
}

Solid torus(Point3 center, double major_radius, double minor_radius, int n_major, int n_minor,
            double crease_angle_deg) {
  require(n_major >= 3 && n_minor >= 3, "torus", "needs at least 3 segments each way");
  require(minor_radius > 0 && minor_radius < major_radius, "torus", "requires 0 < r < R");
  std::vector<Point3> v;
  auto index = [&](int i, int j) {
    return static_cast<std::uint32_t>((i % n_major) * n_minor + (j % n_minor));
  };
  for (int i = 0; i < n_major; ++i)
    for (int j = 0; j < n_minor; ++j) {
      const double theta = 2 * kPi * i / n_major, phi = 2 * kPi * j / n_minor;
      const double rho = major_radius + minor_radius * std::cos(phi);
      v.push_back(center + Vector3{rho * std::cos(theta), rho * std::sin(theta), minor_radius * std::sin(phi)});
    }
  std::vector<IndexedFace> faces;
  for (int i = 0; i < n_major; ++i)
    for (int j = 0; j < n_minor; ++j) {
      IndexedFace f{{index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)}};
      // Outward = away from the tube's core circle.
      const Vector3 c = centroid(v, f[0]) - center;
      const Vector3 radial = normalize(Vector3{c.x, c.y, 0});
      detail::orient_face(v, f, c - major_radius * radial);
      faces.push_back(std::move(f));
    }
  return solid_from_indexed(v, faces, crease_angle_deg);
}

Solid closed_mesh(int target_triangles, unsigned seed) {
  require(target_triangles >= 1, "closed_mesh", "target_triangles must be positive");
  // 2·slices·(stacks − 1) triangles; a square-ish grid keeps the triangles well shaped.
  const int slices = std::max(3, static_cast<int>(std::lround(std::sqrt(target_triangles / 2.0))));
  const int bands = std::max(1, static_cast<int>(std::lround(target_triangles / (2.0 * slices))));
  const UvGrid grid{slices, bands + 1};
  // Radial bumps: a smooth swell plus per-vertex jitter of a fifth of the grid spacing. Each vertex moves
  // only along its ray, so the surface stays star-shaped about the origin and cannot self-intersect.
  const double spacing = kPi / grid.stacks;
  std::vector<Point3> v(grid.vertex_count());
  for (std::uint32_t i = 0; i < v.size(); ++i) {
    const Vector3 d = grid.direction(i);
    const double swell = 0.05 * std::sin(3 * std::atan2(d.y, d.x) + seed % 7) * (1 - d.z * d.z);
    const double r = 1 + swell + 0.2 * spacing * hash_unit(seed, i);
    v[i] = to_point(r * d);
  }
  std::vector<IndexedFace> faces = grid.faces(true);
  // For a triangle on three rays from the origin, det(p0, p1, p2) > 0 exactly when its normal points away
  // from the origin, whatever the radii: orient by the unit directions' triangle.
  for (auto& f : faces) {
    const Vector3 a = grid.direction(f[0][0]), b = grid.direction(f[0][1]), c = grid.direction(f[0][2]);
    if (dot(cross(a, b), c) < 0) std::swap(f[0][1], f[0][2]);
  }
  return solid_from_indexed(v, faces, 0);
}

}  // namespace hlr::stdlib
