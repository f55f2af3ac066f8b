// A brute-force visibility oracle for property tests, written independently of the engine: no engine code
// is reused, every face is tested for every query, and nothing is clever. Is world point P visible?
// Cast the segment from the eye to P (orthographic: from far out along −direction) against every face of
// every object: plane crossing, then even-odd point-in-polygon over all rings in the face plane.
//
// Tolerance: tol = relative_tolerance × scene extent (default 1e-6 × the bounding-box diagonal of all
// vertices and the eye), in world units — a thousand times the engine's Tolerance::kRelative, so any
// configuration within tol of a degeneracy is reported Ambiguous and skipped instead of judged. A face
// hides P only when the segment crosses its plane transversally (eye and P more than tol off the plane on
// opposite sides), the crossing is more than tol inside the polygon (distance to every ring edge > tol),
// more than tol before P along the ray, and — perspective — more than tol beyond the near plane (faces
// are clipped by it). The band test also covers grazing rays: if any ray point within tol of the plane
// (in the eligible range) lands within tol of the polygon, the verdict for that face is Ambiguous.
// A face whose plane contains P (to rounding, 1e-10 × extent) cannot hide P — a line crosses a plane
// once — and is skipped; that is what makes points on a face's own edges decidable.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/hlr/scene.hpp"

namespace hlr::test {

enum class Visibility { Visible, Hidden, Ambiguous };
const char* to_string(Visibility v);

struct Verdict {
  Visibility visibility = Visibility::Visible;
  // The face that decided it (Hidden: the occluder; Ambiguous: the first face in the band); -1 if none
  // (near plane).
  int object = -1;
  int face = -1;
  std::string reason;  // one line, for failure messages
};

class RayCaster {
 public:
  RayCaster(const Scene& scene, const Camera& camera, double relative_tolerance = 1e-6);

  Visibility visibility(Point3 p) const { return classify(p).visibility; }
  Verdict classify(Point3 p) const;
  // The same, with faces `ignore` of object `object` left out (a smooth contour is not hidden by the faces
  // round the face it lies on).
  Verdict classify(Point3 p, std::uint32_t object, const std::vector<std::uint32_t>& ignore) const;
  // How many faces hide p (occlusion level: every face the sight line crosses before p, back faces too);
  // nullopt when any face is Ambiguous for p, or p is not beyond the near plane.
  std::optional<int> surfaces_in_front(Point3 p) const;

  double tolerance() const { return tol_; }  // world units
  double extent() const { return extent_; }  // scene bounding-box diagonal (eye included)
  Point3 center() const { return center_; }
  const Camera& camera() const { return camera_; }

  // Distance from p to the plane of face `face` of object `object` and whether p is within `margin` of the
  // face polygon (in its plane): used to check that intersection lines lie on both surfaces.
  struct FaceProximity {
    double plane_distance = 0;
    double boundary_distance = 0;  // distance from p's projection to the nearest ring edge
    bool inside = false;           // even-odd containment of p's projection
  };
  FaceProximity proximity(std::uint32_t object, std::uint32_t face, Point3 p) const;
  // Signed distance of p to the face's plane (positive on the outward side).
  double signed_distance(std::uint32_t object, std::uint32_t face, Point3 p) const;
  Vector3 normal(std::uint32_t object, std::uint32_t face) const;

 private:
  struct FaceRecord {
    std::uint32_t object = 0, face = 0;
    Vector3 n{};   // unit normal (Newell), outward
    double d = 0;  // plane n·p + d = 0
    Point3 origin{};
    Vector3 u{}, v{};                        // orthonormal basis of the plane
    std::vector<std::vector<Point2>> rings;  // rings in (u, v) coordinates
    Point3 lo{}, hi{};                       // bounding box inflated by tol
  };
  enum class Hit { None, Hidden, Ambiguous };
  struct SightLine {
    Point3 eye{};  // where the sight line to p starts (orthographic: far out along −direction)
    double near_l = 0, near_band = 0;
  };
  // The sight line to p; nullopt (and `verdict` set) when p is at or before the near plane.
  std::optional<SightLine> sight_line(Point3 p, Verdict& verdict) const;
  Hit test_face(const FaceRecord& f, Point3 eye, Point3 p, double near_l, double near_band,
                std::string* why) const;
  const FaceRecord& record(std::uint32_t object, std::uint32_t face) const;

  Camera camera_;
  std::vector<FaceRecord> faces_;
  std::vector<std::size_t> first_face_;  // faces_ index of each object's face 0
  double extent_ = 1, tol_ = 1e-6, on_plane_ = 1e-10;
  Point3 center_{};
};

// ---- 2-D helpers, shared with the checks --------------------------------------------------------------

// Distance between 2-D segments ab and cd (0 when they cross).
double segment_distance(Point2 a, Point2 b, Point2 c, Point2 d);
double point_segment_distance(Point2 p, Point2 a, Point2 b);
// Even-odd containment over all rings (boundary points go either way; callers keep a margin).
bool inside_even_odd(const std::vector<std::vector<Point2>>& rings, Point2 p);

}  // namespace hlr::test
