// Where two triangles cross, constructed exactly: for planes meeting at a grazing angle the common line's
// position in floating point is off by the rounding divided by the angle (at 10⁻⁸ rad, by 10⁻⁸ of the
// triangles' size), so the segment is computed in rationals and rounded once (each coordinate within an ulp).
#pragma once

#include <array>
#include <optional>

#include "core/geometry/vector.hpp"

namespace hlr {

using Triangle3 = std::array<Point3, 3>;

// The segment shared by triangles a and b (closed), its end points rounded; nothing when they are
// apart, meet at one point only, or are coplanar (no line to cross along).
std::optional<std::array<Point3, 2>> exact_triangle_crossing(const Triangle3& a, const Triangle3& b);

}  // namespace hlr
