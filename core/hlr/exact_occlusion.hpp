// The exact fallbacks of the occlusion test (occlusion.cpp), for a triangle hiding a whole edge: the
// triangle's plane is exact, and so are the edge's end points while the edge is not clipped, so both
// halves of the test — behind the plane, inside the picture of the triangle — are signs of world
// orientations. Used only where the floating-point test falls within its tolerance: an edge end within it
// of the plane (near-coplanar twins, a sheet folded onto itself), a piece within it of the triangle's
// outline in the picture (twins stacked exactly, an edge along another's picture). Faces of more corners
// are planar only to Tolerance::kPlanarity and keep the tolerance rule: within it is on the face.
#pragma once

#include "core/camera/camera.hpp"
#include "core/geometry/polygon2d.hpp"
#include "core/hlr/frame_setup.hpp"

namespace hlr {

class ExactTriangleTest {
 public:
  // False when the occluder is not a triangle or the candidate is not a whole edge (clipped, or a line
  // where faces cross): the tolerance rule then stands.
  bool prepare(const FrameSetup& setup, const Camera& camera, const Candidate& c, const Occluder& o);

  // The side of the candidate's end (0: view0, 1: view1) as g measures it in occlusion.cpp: > 0 on the
  // eye's side of the plane, < 0 behind it, 0 exactly on it.
  int side(int end) const;
  // Where the candidate crosses the plane (view parameter), when its ends lie strictly on both sides.
  double root() const;
  // Where the candidate's point at view parameter t lies against the triangle's picture: Inside when the
  // sight line through it passes strictly inside the triangle, Boundary when exactly through its outline
  // (`side` then says through which side, k from corner k to k + 1, when exactly one; else −1).
  PointClass shadow(double t, int& side) const;
  // Where the candidate crosses the sight plane of the triangle's side k (view parameter), or −1 when its
  // ends do not lie strictly on both sides: in the picture, where it crosses that side's line — which for
  // lines nearly parallel in the picture floating point places anywhere along them.
  double sight_crossing(int k) const;

 private:
  Point3 corner_[3];
  Point3 p0_, p1_;  // world points of the candidate's view0, view1
  int sign_ = 1;    // turns a world orientation into the side g measures
  bool perspective_ = true;
  Point3 eye_{};
  Vector3 direction_{};
};

}  // namespace hlr
