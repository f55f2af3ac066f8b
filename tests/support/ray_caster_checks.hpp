// Property checks of an engine result against the RayCaster oracle:
//   (a) nothing drawn is hidden: 7 interior samples per drawn piece, none may be Hidden (Ambiguous is
//       skipped); pieces lie on their edge, carry consistent picture coordinates, stay in the frame, are of
//       a drawable kind, and pieces of one edge do not overlap;
//   (b) nothing visible is missing: samples along every drawn-candidate edge (Feature, Boundary, Marking,
//       Free; Smooth only on the contour) that the oracle calls Visible and that lie inside the frame must
//       be covered by a returned piece of that object and edge (picture distance < 1e-6 × picture extent;
//       edges seen end-on, shorter than 10 such distances on the picture, are skipped) — or, where another
//       solid's edge lies on it (drawn once), by a visible piece of any object through that world point;
//   (c) intersection lines: every Intersection piece lies on a face of both its objects and is not Hidden;
//       and, between solids and within one solid (faces sharing at most one vertex), open or closed, every
//       sampled point where two faces cross strictly inside both that the oracle calls Visible is covered
//       by an Intersection piece of that pair of objects.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/hlr/scene.hpp"
#include "core/hlr/visible_segment.hpp"
#include "tests/support/ray_caster.hpp"

namespace hlr::test {

struct CheckOptions {
  int edge_samples = 17;           // per candidate edge, at (i + 0.5)/n
  double picture_relative = 1e-6;  // coverage distance, × picture extent
  bool intersections = true;       // run (c)
  std::size_t max_failures = 12;   // stop collecting messages after this many
};

struct CheckReport {
  std::size_t drawn_samples = 0, drawn_ambiguous = 0;                  // (a)
  std::size_t edge_samples = 0, edge_visible = 0, edge_ambiguous = 0;  // (b)
  std::size_t intersection_samples = 0, intersection_expected = 0;     // (c)
  std::vector<std::string> failures;
  std::vector<std::string> ambiguous_examples;  // the oracle's reasons for the first few Ambiguous samples
  bool ok() const { return failures.empty(); }
  std::string summary() const;  // counts, then the failures one per line
};

// Fractions of a piece's length at which it is sampled: 1e-3 from each end and five evenly between.
inline constexpr std::array<double, 7> kSegmentSampleFractions = {1e-3,    1.0 / 6, 2.0 / 6, 3.0 / 6,
                                                                  4.0 / 6, 5.0 / 6, 1 - 1e-3};
std::vector<Point3> segment_samples(const VisibleSegment& s);

// Whether an edge is a drawn candidate from this camera: Feature, Boundary, Marking, Free always; Flat
// never; Smooth when exactly one adjacent face faces the eye (Ambiguous when a face is nearly edge-on).
enum class Candidate { Yes, No, Ambiguous };
Candidate drawn_candidate(const RayCaster& oracle, std::uint32_t object, const Solid& solid,
                          const SolidEdge& e);

// A point with full precision, for failure messages.
std::string str(Point3 p);
std::string str(Point2 p);
// Whether picture point s lies in the camera's frame grown by `margin` (negative: shrunk); true without one.
bool in_frame(const Camera& c, Point2 s, double margin);
// Whether world point p lies beyond the near plane (always, orthographic).
bool in_front(const Camera& c, Point3 p);

// Picture-coordinate scale for coverage: the frame's diagonal, else the bounding box of the pieces' ends
// and the vertices (perspective: only those within 45° of the view axis, and at least the 90° field).
double picture_extent(const Scene& scene, const Camera& camera, const FrameResult& result);

CheckReport check_drawn_not_hidden(const Scene& scene, const RayCaster& oracle, const FrameResult& result,
                                   const CheckOptions& options = {});
CheckReport check_visible_not_missing(const Scene& scene, const RayCaster& oracle, const FrameResult& result,
                                      const CheckOptions& options = {});
CheckReport check_intersections(const Scene& scene, const RayCaster& oracle, const FrameResult& result,
                                const CheckOptions& options = {});
// All three, merged.
CheckReport check_frame(const Scene& scene, const Camera& camera, const FrameResult& result,
                        const CheckOptions& options = {});

}  // namespace hlr::test
