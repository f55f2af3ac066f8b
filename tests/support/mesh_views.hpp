// Meshes made face by face and random views of them, shared by the suites that check generated meshes
// against the oracles (self-intersecting, near-degenerate).
#pragma once

#include <vector>

#include "core/camera/camera.hpp"
#include "core/solid/solid.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::test {

// The solid with the given vertices and faces (one ring each), built as an imported mesh would be; a
// mesh that does not build is a test failure (and a unit box is returned).
Solid mesh_solid(const std::vector<Point3>& vertices, const std::vector<std::vector<VertexIndex>>& faces,
                 double crease_angle_deg = 0);

// A solid's faces (without holes) as triangles, ear-clipped as the importer does, so that moving a vertex
// keeps every face planar.
std::vector<std::vector<VertexIndex>> triangles_of(const Solid& s);

// A view from a random side at 3–5 times `size` from `center`: lookat with fov 30–60°, or (every third
// n) orthographic.
Camera random_view(Rng& r, Point3 center, double size, int n);

}  // namespace hlr::test
