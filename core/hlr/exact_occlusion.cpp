#include "core/hlr/exact_occlusion.hpp"

#include "core/geometry/exact_predicates.hpp"

namespace hlr {

bool ExactTriangleTest::prepare(const FrameSetup& setup, const Camera& camera, const Candidate& c,
                                const Occluder& o) {
  if (!setup.scene || c.source != SegmentSource::Edge) return false;
  const Solid& occluder = *setup.scene->objects[o.object].solid;
  const Face& face = occluder.faces[o.face];
  if (face.rings.size() != 1 || face.rings[0].vertices.size() != 3) return false;
  // Its picture polygon must be the triangle itself, corner k at point k (not cut by the near plane): the
  // seams are read by point.
  if (o.ring_count != 1 || setup.ring_ends[o.first_ring] - o.first_point != 3) return false;
  for (int k = 0; k < 3; ++k) {
    corner_[k] = occluder.vertices[face.rings[0].vertices[k]];
    if (!(camera.project(corner_[k]) == setup.polygon_points[o.first_point + k])) return false;
  }
  // A candidate clipped by the near plane no longer ends at its vertices: mapping them again gives the
  // very doubles of its view points only when it was not.
  const Solid& own = *setup.scene->objects[c.object].solid;
  const SolidEdge& e = own.edges[c.edge];
  const Point3 a = own.vertices[e.v0], b = own.vertices[e.v1];
  const Point3 va = camera.view(a), vb = camera.view(b);
  if (va == c.view0 && vb == c.view1) {
    p0_ = a, p1_ = b;
  } else if (vb == c.view0 && va == c.view1) {
    p0_ = b, p1_ = a;
  } else {
    return false;
  }
  // g's plane is the outward one seen in view space, where a mirroring view map turns orientations.
  sign_ = (o.eye_side > 0 ? 1 : -1) * setup.handedness;
  perspective_ = camera.projection == Projection::Perspective;
  if (perspective_) {
    eye_ = camera.eye_world();
  } else {
    direction_ = camera.direction_world();
  }
  return true;
}

int ExactTriangleTest::side(int end) const {
  const Point3 p = end == 0 ? p0_ : p1_;
  if (p == corner_[0] || p == corner_[1] || p == corner_[2]) return 0;  // a shared vertex (commonest)
  return sign_ * orient3d(corner_[0], corner_[1], corner_[2], p);
}

double ExactTriangleTest::root() const {
  return plane_crossing(corner_[0], corner_[1], corner_[2], p0_, p1_);
}

double ExactTriangleTest::sight_crossing(int k) const {
  const Point3 a = corner_[k], b = corner_[(k + 1) % 3];
  const int s0 =
      perspective_ ? orient3d(a, b, eye_, p0_) : orient3d_along_direction(a, b, direction_, p0_, p0_, 0);
  const int s1 =
      perspective_ ? orient3d(a, b, eye_, p1_) : orient3d_along_direction(a, b, direction_, p1_, p1_, 0);
  if (s0 * s1 >= 0) return -1;
  return perspective_ ? plane_crossing(a, b, eye_, p0_, p1_)
                      : plane_crossing_along_direction(a, b, direction_, p0_, p1_);
}

PointClass ExactTriangleTest::shadow(double t, int& side) const {
  // The sight planes through each side of the triangle (and the eye, or along the view direction): the
  // point is inside when it lies strictly on the third corner's side of all three. An edge of the
  // triangle itself is on its own sight plane.
  side = -1;
  int zeros = 0;
  for (int k = 0; k < 3; ++k) {
    const Point3 a = corner_[k], b = corner_[(k + 1) % 3], opposite = corner_[(k + 2) % 3];
    if ((p0_ == a && p1_ == b) || (p0_ == b && p1_ == a)) {
      side = k;
      return PointClass::Boundary;
    }
    const int at = perspective_ ? orient3d_along(a, b, eye_, p0_, p1_, t)
                                : orient3d_along_direction(a, b, direction_, p0_, p1_, t);
    const int ref = perspective_ ? orient3d(a, b, eye_, opposite)
                                 : orient3d_along_direction(a, b, direction_, opposite, opposite, 0);
    if (ref == 0) {  // seen edge-on: a triangle of no area hides nothing
      side = -1;
      return PointClass::Boundary;
    }
    if (at == 0) {
      side = k;
      ++zeros;
    } else if (at != ref) {
      return PointClass::Outside;
    }
  }
  if (zeros > 1) side = -1;  // through a corner
  return zeros > 0 ? PointClass::Boundary : PointClass::Inside;
}

}  // namespace hlr
