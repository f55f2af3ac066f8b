// Geometry of planar faces shared by the builder and Solid::transformed: the Newell plane, a 2-D frame
// in the face's plane with even-odd containment, and the dihedral classification of an edge.
// Not part of the public API.
#pragma once

#include <vector>

#include "core/geometry/vector.hpp"
#include "core/solid/solid.hpp"

namespace hlr::solid_detail {

// Plane of a ring by Newell's method: normal along the ring's Newell normal, through the mean of its
// vertices (the least-squares choice for that normal). `twice_area` receives |Newell normal|; the
// normal is zero when the ring has no area.
Plane newell_plane(const std::vector<Point3>& vertices, const Ring& ring, double* twice_area = nullptr);
// The same from the ring's Newell normal, when it is known already.
Plane newell_plane(const std::vector<Point3>& vertices, const Ring& ring, Vector3 newell);

// An orthonormal frame (u, v) in a plane with normal n, u × v = n: a ring counter-clockwise seen from
// the side n points to has positive signed area in (u, v) coordinates.
struct FaceFrame {
  Point3 origin;
  Vector3 u, v;
  static FaceFrame from_normal(Vector3 unit_normal, Point3 origin);
  Point2 to_2d(Point3 p) const {
    const Vector3 d = p - origin;
    return {dot(d, u), dot(d, v)};
  }
};

using Polygon2 = std::vector<Point2>;  // a closed ring in frame coordinates

double signed_area(const Polygon2& ring);

enum class Containment { Outside, Boundary, Inside };

// Even-odd containment of p in the region bounded by `rings`; Boundary when p lies within `tolerance`
// of any ring edge.
Containment classify_point(Point2 p, const std::vector<Polygon2>& rings, double tolerance);

// Whether segments ab and cd cross at a point interior to both (touching within `tolerance`, at an end
// point or collinearly, does not count).
bool segments_cross(Point2 a, Point2 b, Point2 c, Point2 d, double tolerance);

// Kind of an edge between two faces with unit outward normals nl (left face, traversing the edge
// along `direction`) and nr (right face), and whether it is concave.
struct DihedralClass {
  EdgeKind kind;
  bool concave;
};
DihedralClass classify_dihedral(Vector3 direction, Vector3 nl, Vector3 nr, double crease_angle_deg);

}  // namespace hlr::solid_detail
