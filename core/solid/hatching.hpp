// Hatching: the shading a pen plotter can draw. Parallel lines are laid on each face of a solid, in the
// solid's own coordinates, clipped to the face (holes too) and added to it as Hatch edges. The engine then
// hides them exactly as it hides markings — drawn where visible, hiding nothing, gone with a back face —
// and the devices draw them in the solid's hatch pen. Lines laid in space, not on the page, stay on their
// faces when the camera or the solid moves, and coplanar faces (a triangulated flat face) share lines
// that meet end to end across their common edge.
#pragma once

#include <cstddef>
#include <optional>

#include "core/geometry/vector.hpp"
#include "core/solid/solid.hpp"

namespace hlr {

struct HatchSpec {
  double spacing = 1;  // between neighbouring lines of the densest set, in the solid's units; > 0
  // The lines' direction on each face, in degrees from the face's horizontal (z × n: on a sphere the
  // latitudes, on a wall the level lines), turning towards the face's "up" (n × horizontal). A face
  // facing straight up or down takes the x axis as its horizontal.
  double angle_deg = 45;
  // Towards the light (any length but zero): each face is hatched by how dark it is, its darkness
  // d = 1 − max(0, n·l) (Lambert), in four tones that share lines — d < ¼ bare, < ½ every fourth line,
  // < ¾ every second line, else every line and a crossing set every second line. Unset: every face at
  // `spacing`.
  std::optional<Vector3> light;
  bool cross = false;  // a second set at right angles on every hatched face, at the face's spacing
  // Instead of `angle`: the lines are where parallel planes normal to this direction cut the faces,
  // `spacing` apart in space (a face tilted to them gets its lines further apart). Every face shares the
  // planes, so the lines run on unbroken from face to face — on a scan of small triangles, long curves
  // instead of a dash a triangle. The crossing set is cut by planes normal to planes × z.
  std::optional<Vector3> planes;
  // Only the faces lying in this plane are hatched (their outward normal the plane's, every vertex within
  // `in_plane_tolerance` of it): the cut faces of a section.
  std::optional<Plane> only_in_plane;
  double in_plane_tolerance = 0;
};

// How many lines hatching `solid` as `spec` lays at most (a line across a non-convex face may give
// several pieces): for the caller's limits, before anything is made.
std::size_t hatch_line_bound(const Solid& solid, const HatchSpec& spec);

// `solid` with its hatch lines added (EdgeKind::Hatch, each on its face, two new vertices each).
// Throws std::invalid_argument for a spacing that is not finite and positive, or a zero light or planes
// normal.
Solid hatched(const Solid& solid, const HatchSpec& spec);

}  // namespace hlr
