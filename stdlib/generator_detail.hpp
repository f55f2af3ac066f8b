// Internals shared by the generator files (primitives, meshes, cities); not part of the stdlib API.
#pragma once

#include <string>
#include <vector>

#include "core/geometry/affine3.hpp"
#include "core/geometry/vector.hpp"
#include "core/solid/solid.hpp"
#include "stdlib/generators.hpp"

namespace hlr::stdlib::detail {

// Throws std::invalid_argument("<function>(): <what>") unless `ok`.
void require(bool ok, const char* function, const std::string& what);

// Twice the signed area of a 2-D polygon (positive when counter-clockwise).
double signed_area2(const std::vector<Point2>& polygon);

// Extrudes `outer` (made counter-clockwise) with `holes` (made clockwise) along w ∈ [w0, w1] in the local
// frame (u, v, w); world = worldFromLocal.apply({u, v, w}). worldFromLocal must preserve orientation
// (determinant > 0) so that faces stay outward.
Solid extrude(std::vector<Point2> outer, std::vector<std::vector<Point2>> holes, double w0, double w1,
              const Affine3& worldFromLocal, double crease_angle_deg = 0);

// Reverses every ring of `face` when its Newell normal points against `outward` (used by the meshes,
// whose faces are easier to list in one fixed order and orient afterwards).
void orient_face(const std::vector<Point3>& vertices, IndexedFace& face, Vector3 outward);

}  // namespace hlr::stdlib::detail
