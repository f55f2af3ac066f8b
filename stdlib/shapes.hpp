// More solid generators for scripts (issue 3): pyramids, the Platonic solids, cones and frustums,
// extrusions of planar polygons in 3-D, surfaces of revolution, sweeps along polylines and heightfields.
// Like generators.hpp, every result is built through SolidBuilder (so it satisfies the Solid invariants)
// and faces are counter-clockwise seen from outside. Generated faces are planar by construction, not
// merely within tolerance (a polygon given to pyramid() or extrude() need only be planar within the
// builder's tolerance, and its face is then exactly as planar as given). Bad arguments throw
// std::invalid_argument("<function>(): <parameter> ..."), naming the parameter as a script names it
// (outline, hole k, apex, v, r, h, top, sides, profile, segments, angle, path, values, dx, dy, base,
// crease); a builder failure would be a bug here (std::runtime_error). Point indices in messages count
// from 0, like script lists.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/vector.hpp"
#include "core/solid/solid.hpp"

namespace hlr::stdlib {

// ---- polygon checks (shape_checks.cpp) ----------------------------------------------------------------

// Where two edges of some rings meet although they should not. Edge e of a ring runs from point e to
// point e + 1 (the last edge of a closed ring back to point 0). ring_a/edge_a == ring_b/edge_b means
// that edge has zero length.
struct RingDefect {
  std::size_t ring_a = 0, edge_a = 0, ring_b = 0, edge_b = 0;
};

// The first pair of edges that cross, touch or overlap among `rings` (each a closed polygon, or an open
// polyline when `closed` is false), other than two neighbouring edges of one ring meeting only at their
// shared corner; nullopt when the rings are simple and pairwise disjoint. Distances up to 1e-9 of the
// largest coordinate (or of `extent`, if larger: the size of the 3-D coordinates the rings were projected
// from) count as touching — the builder's coincidence tolerance. Expected O(n log n) for n edges in
// practice (edges are swept in x).
std::optional<RingDefect> find_ring_defect(const std::vector<std::vector<Point2>>& rings, bool closed = true,
                                           double extent = 0);

// The defect in words for an error message, naming ring k by names[k] and edges by their 0-based end
// points: "edges 2–3 and 5–6 of the outline cross or touch", "hole 0 crosses the outline (…)".
std::string describe_ring_defect(const RingDefect& defect, const std::vector<std::string>& names,
                                 const std::vector<std::vector<Point2>>& rings, bool closed = true);

// ---- polyhedra (pyramid: extrude.cpp; the Platonic solids: platonic.cpp) -----------------------------

// A pyramid over `outline` (a simple planar polygon in 3-D, either orientation, at least 3 corners; a
// repeated closing point is ignored) with its tip at `apex`, which must lie off the outline's plane (it
// may lie anywhere else: an oblique pyramid). Faces: the base, then one triangle per outline edge.
Solid pyramid(const std::vector<Point3>& outline, Point3 apex);

// The Platonic solids, centred at the origin, with circumradius r (> 0). Faces are found as the convex
// hull of the vertices, so every face is exactly one planar polygon and every edge a convex Feature edge.
//   tetrahedron: vertices at alternate cube corners (r/√3)(±1, ±1, ±1) with an even number of minus signs;
//   hexahedron: the axis-aligned cube (r/√3)(±1, ±1, ±1);
//   octahedron: (±r, 0, 0), (0, ±r, 0), (0, 0, ±r);
//   dodecahedron: the cube corners plus the cyclic permutations of (0, ±1/φ, ±φ), scaled by r/√3;
//   icosahedron: the cyclic permutations of (0, ±1, ±φ), scaled by r/√(1 + φ²).
Solid tetrahedron(double r = 1);
Solid hexahedron(double r = 1);
Solid octahedron(double r = 1);
Solid dodecahedron(double r = 1);
Solid icosahedron(double r = 1);

// ---- solids of revolution (revolve.cpp) ----------------------------------------------------------------

// A cone (top_radius 0: apex at (0, 0, height)) or frustum on a regular `sides`-gon base of circumradius
// `radius` centred at the origin on z = 0, the first corner on +x (like cylinder()). radius may be 0 when
// top_radius > 0 (an upside-down cone). Faces: the base and top polygons and one side face per side
// (triangles for a cone, isosceles trapezoids for a frustum). Side edges are Smooth when 360/sides is
// below the crease angle.
Solid cone(double radius, double height, double top_radius = 0, int sides = 32, double crease_angle_deg = 30);

// Revolves `profile`, points (r, z) with r ≥ 0 in the x–z half-plane, counter-clockwise about the z axis
// by `angle_deg` ∈ (0, 360] in `segments` steps (the first copy at angle 0, in the x–z plane). The profile
// is a closed polygon when its first and last points are equal, else an open polyline. It must be simple
// and may meet the axis only (a) at the ends of an open profile, or (b) along one stretch of a closed
// profile (which then counts as an open profile whose ends are on the axis). Leading or trailing runs of
// axis points of an open profile are trimmed to one point.
//   * Full revolution (360°): a closed solid when the profile is closed (genus 1, a ring) or both ends
//     are on the axis (genus 0); otherwise an open surface (a tube or a bowl) with Boundary rims — a
//     profile is never capped implicitly: end it on the axis, or close it, to get a solid.
//   * Partial angle: closed by two planar profile faces (at angle 0 and angle_deg) when the profile is
//     closed or both ends are on the axis; otherwise an open surface without profile faces.
// Faces between two profile points at two angles are isosceles trapezoids (hence planar); at an axis
// point they are triangles around one pole vertex (no degenerate quads). A profile segment at constant
// z becomes one planar face: a regular polygon (disk), a polygon with a hole (annulus) or, for a partial
// angle, the corresponding sector. For a closed solid the profile's orientation does not matter; for an
// open surface the outside is on the right of the profile walking from its first to its last point (a
// profile going up at r > 0 faces away from the axis). segments ≥ 3 for a full revolution, ≥ 1 with less
// than 180° per step otherwise.
Solid revolve(const std::vector<Point2>& profile, int segments = 32, double angle_deg = 360,
              double crease_angle_deg = 30);

// ---- extrusions and sweeps (extrude.cpp, sweep.cpp) -------------------------------------------------

// Sweeps `outline` (a simple planar polygon in 3-D, non-convex allowed, either orientation) with its
// `holes` (simple, inside the outline, pairwise disjoint, on its plane) along `direction`, which must not
// be parallel to the plane (oblique is fine: the side faces are parallelograms). The input points are
// kept exactly as the vertices of the base; the other cap is the base moved by `direction`. Faces: base,
// cap (both with the holes), then one side per outline edge and per hole edge; all outward whatever the
// orientation of the rings and the sign of `direction`.
Solid extrude(const std::vector<Point3>& outline, Vector3 direction,
              const std::vector<std::vector<Point3>>& holes = {});

// Sweeps the 2-D `profile` (a simple polygon, either orientation: the outline) along the polyline
// `path`, with mitred joints: at each inner corner the cross-section lies in the plane bisecting the two
// segments, so every side face is one planar quad. The profile's frame is carried along the path by the
// minimal rotation at each corner (parallel transport: a discrete rotation-minimising frame), which is
// exactly what makes the mitre sections of consecutive segments coincide. At the start, profile x and y
// map to X = Y × t and Y = world +z made perpendicular to the first direction t (world +y when t is
// vertical): for a path along +z the profile keeps its x–y orientation. The profile's origin follows the
// path. Caps at both ends (perpendicular to the end segments); a closed path (first point == last) gives a
// ring without caps, which needs a frame that returns to itself — always true for a planar path; a
// non-planar closed path that twists the frame is rejected. Rejected too: fewer than 2 points (3 distinct
// for a closed path), zero-length segments, reversals, and corners too sharp for the profile (a mitred
// section would reach past the neighbouring one). Faces: one quad per profile edge and path segment, then the
// two caps.
Solid sweep(const std::vector<Point2>& profile, const std::vector<Point3>& path,
            double crease_angle_deg = 30);

// ---- heightfields (heightfield.cpp) --------------------------------------------------------------------

// A terrain over the grid x = j·dx, y = i·dy with z = heights[i][j] (rows i along y, columns j along x;
// at least 2 × 2, every row the same length, all finite). A cell whose four corners are coplanar stays
// one quad; any other cell is split into two triangles along its diagonal (i, j)–(i + 1, j + 1). Without
// `base` an open surface facing +z (Boundary rim); with `base` (below every height) a closed block: four
// side walls, each one planar polygon following the terrain's border, and a rectangular bottom at z = base.
Solid heightfield(const std::vector<std::vector<double>>& heights, double dx = 1, double dy = 1,
                  std::optional<double> base = std::nullopt, double crease_angle_deg = 30);

}  // namespace hlr::stdlib
