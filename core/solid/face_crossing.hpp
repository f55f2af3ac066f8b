// Where two planar faces cross: the pieces of their planes' common line that lie strictly inside both
// faces. Used for the lines where solids interpenetrate (core/hlr/intersection_lines) and where one solid
// passes through itself (self_crossings).
#pragma once

#include <cstdint>
#include <vector>

#include "core/solid/solid.hpp"

namespace hlr {

struct CrossingPiece {
  Point3 p0, p1;
};

// Buffers reused from one call to the next.
struct FaceCrossingScratch {
  std::vector<Point2> points;
  std::vector<std::uint32_t> ring_ends;
  std::vector<double> breaks;
  std::vector<std::pair<double, double>> in_a, in_b;
};

// Appends to `out` the pieces where face `fa` of `sa` and face `fb` of `sb` cross, each more than
// `tolerance` long. Two triangles at a grazing angle (Tolerance::kExactCrossingAngle) are met exactly,
// and have none only when exactly coplanar or parallel; other faces with normals within
// Tolerance::kCoplanarAngle have none.
void face_crossings(const Solid& sa, FaceIndex fa, const Solid& sb, FaceIndex fb, double tolerance,
                    FaceCrossingScratch& scratch, std::vector<CrossingPiece>& out);

// False when every vertex of face `f` of `s` lies more than `tolerance` on one side of `plane`: the face
// cannot meet it. A cheap test to run before face_crossings.
bool face_meets_plane(const Solid& s, FaceIndex f, const Plane& plane, double tolerance);

}  // namespace hlr
