// An exact visibility oracle for scenes of triangles, for the near-degenerate cases the tolerant
// RayCaster leaves undecided (folded slivers, near-coplanar twins, lines crossing at grazing angles).
// Written apart from the engine: its own rational arithmetic (GMP), no engine predicate reused.
//
// A point P is hidden when some triangle separates it from the eye strictly: P and the eye lie on
// opposite sides of the triangle's plane (orthographic: P lies behind the plane as seen along the view
// direction) and the sight line through P pierces the triangle's interior — three orientations of the
// same strict sign. Both are signs of determinants of the input doubles and of P, which is a rational
// point (an edge's end points and a double parameter), so every verdict is exact. A point on a triangle's
// plane is never hidden by it (a line meets a plane once); a sight line through a triangle's boundary is
// Ambiguous unless another triangle hides the point strictly.
//
// Each determinant is first evaluated in doubles; a result larger than 1e-12 of the sum of its terms'
// magnitudes (a thousand times the rounding) is taken, anything else recomputed in rationals.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/hlr/scene.hpp"
#include "core/hlr/visible_segment.hpp"
#include "tests/support/ray_caster.hpp"

namespace hlr::test {

struct ExactPoint {
  mpq_class x, y, z;
  Point3 approx() const { return {x.get_d(), y.get_d(), z.get_d()}; }
};
ExactPoint exact(Point3 p);
// a + t·(b − a), exactly.
ExactPoint exact_lerp(Point3 a, Point3 b, double t);

// Where two triangles of the scene cross, exactly: the end points of the segment they share.
struct ExactCrossing {
  std::uint32_t object0 = 0, face0 = 0, object1 = 0, face1 = 0;
  ExactPoint p0, p1;
};

class ExactOracle {
 public:
  // Every face of every object must be a triangle of one ring (ADD_FAILURE otherwise).
  ExactOracle(const Scene& scene, const Camera& camera);

  Visibility visibility(const ExactPoint& p) const;

  // The segments where triangles cross (pairs sharing at most one vertex, not coplanar), within one object
  // and between objects.
  std::vector<ExactCrossing> crossings() const;

  // Whether the eye lies exactly on the plane of face `face` of `object` (0), in front of it (1: it faces
  // the eye) or behind it (−1).
  int facing(std::uint32_t object, std::uint32_t face) const;

 private:
  struct Triangle {
    std::uint32_t object = 0, face = 0;
    Point3 a, b, c;
    VertexIndex va = 0, vb = 0, vc = 0;
    Point3 lo, hi;  // bounding box
  };
  int side(const Triangle& t, const ExactPoint& p) const;  // sign of (b − a) × (c − a) · (p − a)
  int eye_side(const Triangle& t) const;
  // Sign of det[u − p, v − p, r] with r the direction from p towards the eye.
  int sight_orientation(Point3 u, Point3 v, const ExactPoint& p) const;

  Camera camera_;
  bool perspective_ = true;
  Point3 eye_{};
  Vector3 toward_eye_{};  // orthographic: −direction
  double extent_ = 1;
  Point3 lo_{}, hi_{};
  std::vector<Triangle> triangles_;
  std::vector<int> eye_sides_;  // eye_side of each triangle
};

// The drawing against the exact oracle, in samples along the drawn pieces and the edges that are drawn
// candidates (Feature, Boundary, Marking, Free; Smooth where exactly one face faces the eye), and along
// the exact crossings of triangles. A visible sample of an edge is covered by a drawn piece of that edge,
// or — two edges on one line of the picture are drawn once — by any drawn piece through its picture point.
struct ExactReport {
  std::size_t drawn_samples = 0, drawn_hidden = 0;  // samples of drawn pieces the oracle hides
  std::size_t edge_samples = 0, edge_visible = 0, edge_missing = 0;
  std::size_t crossing_samples = 0, crossing_visible = 0, crossing_missing = 0;
  std::size_t ambiguous = 0;
  std::vector<std::string> failures;  // the first few, one line each
  bool ok() const { return drawn_hidden == 0 && edge_missing == 0 && crossing_missing == 0; }
  std::string summary() const;
};

struct ExactCheckOptions {
  int edge_samples = 33;  // per candidate edge and per crossing
  // A visible sample within this × scene extent of a drawn piece is covered. Points the engine constructs
  // (where an edge passes behind a face, where faces cross) are off by the rounding over the angle they
  // are cut at: 10⁻⁸ of the size for an edge meeting a plane at 10⁻⁸ rad.
  double coverage = 1e-7;
  std::size_t max_failures = 8;
};

ExactReport check_exact(const Scene& scene, const Camera& camera, const FrameResult& result,
                        const ExactCheckOptions& options = {});

}  // namespace hlr::test
