// Generators of validated solids for scripts, tests and benchmarks. Every generator builds through
// SolidBuilder, so its output satisfies the Solid invariants (solid.hpp); a build failure is a generator
// bug and throws std::runtime_error carrying the builder's diagnostics. Faces are counter-clockwise seen
// from outside. Bad arguments (a sphere with 2 slices, a negative size) throw std::invalid_argument.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/geometry/affine3.hpp"
#include "core/geometry/vector.hpp"
#include "core/solid/solid.hpp"

namespace hlr::stdlib {

// ---- building blocks --------------------------------------------------------------------------------

// One face given by vertex indices: rings[0] the outer loop (counter-clockwise seen from outside), then
// holes (clockwise seen from outside).
using IndexedFace = std::vector<std::vector<std::uint32_t>>;

struct IndexedLine {
  std::uint32_t a = 0, b = 0;
};

// A solid from indexed vertices and faces (and optional lines: markings when both ends lie on one face,
// else free lines). Throws std::runtime_error with the builder's diagnostics if the data is invalid.
Solid solid_from_indexed(const std::vector<Point3>& vertices, const std::vector<IndexedFace>& faces,
                         double crease_angle_deg = 0, const std::vector<IndexedLine>& lines = {});

// The `sides` corners of a regular polygon, counter-clockwise, the first at angle `phase_deg`.
std::vector<Point2> regular_polygon(int sides, double radius, Point2 center = {}, double phase_deg = 0);

// ---- primitives (primitives.cpp) --------------------------------------------------------------------

// Axis-aligned box; requires min < max on every axis. 8 vertices, 6 faces, 12 edges.
Solid box(Point3 min, Point3 max);

// A box of full side lengths `size` centred at `center`, rotated by `angle_deg` about `axis` (through the
// centre). Built directly from the rotated corners.
Solid rotated_box(Point3 center, Vector3 size, Vector3 axis, double angle_deg);

// Extrusion of a simple polygon (either orientation) with holes along z from z0 to z1 (z0 < z1). Faces:
// bottom, top (both with the holes), one side per polygon edge and per hole edge.
Solid prism(const std::vector<Point2>& polygon, const std::vector<std::vector<Point2>>& holes, double z0,
            double z1);

// An L-shaped prism: the L outline in the x–z plane, extruded along +y by size.y. The foot spans
// x ∈ [0, size.x] with height foot_height; the upright spans x ∈ [0, upright_width] up to size.z.
// Pfister's L prism is l_block({0,0,0}, {2,1,2}, 1, 1) (outline in x–z, depth 1). 8 faces, concave.
Solid l_block(Point3 origin, Vector3 size, double upright_width, double foot_height);

// A closed flight of `steps` steps rising along +x, `width` along +y, from the origin: step i covers
// x ∈ [i·run, (i+1)·run] at height (i+1)·rise. Concave; 2·steps + 4 faces.
Solid stairs(int steps, double width, double rise, double run);

// A regular `sides`-gon prism standing on `base_center`. Side edges are Smooth when the crease angle
// exceeds 360/sides degrees.
Solid cylinder(Point3 base_center, double radius, double height, int sides, double crease_angle_deg = 0);

// A rectangular plate spanning min..max with holes_x × holes_y regular `hole_sides`-gon holes through it
// (thickness along z), each hole `hole_fraction` of its cell wide. Top and bottom are faces with holes.
Solid plate_with_holes(Point3 min, Point3 max, int holes_x, int holes_y, double hole_fraction = 0.5,
                       int hole_sides = 4);

// A box without its top face: an open surface (closed == false) whose rim edges are Boundary edges.
Solid open_box(Point3 min, Point3 max);

// A box with two marking lines on its top face (an X inset from the corners by a quarter) and a free
// line (a mast) rising from one end of the X by half the box height. 6 faces, 12 + 3 edges.
Solid marked_box(Point3 min, Point3 max);

// ---- curved-surface meshes (meshes.cpp) --------------------------------------------------------------

// UV sphere: `slices` ≥ 3 around z, `stacks` ≥ 2 from pole to pole; triangles at the poles, planar
// isosceles-trapezoid quads elsewhere. Faces: slices·stacks. Vertices: slices·(stacks−1) + 2.
Solid sphere(Point3 center, double radius, int slices, int stacks, double crease_angle_deg);

// Torus around the z axis through `center`: major radius R, tube radius r (0 < r < R). Its quads are
// isosceles trapezoids (mirror-symmetric about the bisecting planes), hence planar. Faces:
// n_major·n_minor; genus 1 (V − E + F = 0).
Solid torus(Point3 center, double major_radius, double minor_radius, int n_major, int n_minor,
            double crease_angle_deg);

// A closed triangle mesh of about `target_triangles` triangles (exactly 2·n·k for the chosen grid; within
// a few percent of the target for targets ≥ 100): a triangulated UV sphere of radius ≈ 1 at the origin
// whose vertices are pushed along their rays by deterministic pseudo-random bumps (from `seed`), so almost
// no two adjacent triangles are coplanar and nearly every edge is a Feature edge at crease 0. Every vertex
// stays on its own ray from the origin, so the surface never intersects itself.
Solid closed_mesh(int target_triangles, unsigned seed);

// ---- scenes (cities.cpp) -------------------------------------------------------------------------------

struct CityOptions {
  double cell = 10;          // grid pitch of the blocks
  double street = 3;         // minimum gap between neighbouring buildings
  double min_height = 4;
  double max_height = 30;
  double tower_chance = 0.15;  // fraction of buildings that are L-shaped (a tower on a podium)
  bool ground = true;        // add a ground plate under the city (top face at z = 0)
};

// n_x × n_y buildings on a regular grid (x, y ≥ 0, ground at z = 0), random footprints and heights from
// `seed`. Heights do not grow with the grid, so seen from a fixed elevation the depth complexity stays
// roughly constant as the city grows. Buildings come first, the ground plate (if any) last.
std::vector<Solid> box_city(int n_blocks_x, int n_blocks_y, unsigned seed, const CityOptions& options = {});

// Extent of a city grid in x and y (for placing a camera).
inline Vector2 city_extent(int n_blocks_x, int n_blocks_y, const CityOptions& options = {}) {
  return {n_blocks_x * options.cell, n_blocks_y * options.cell};
}

}  // namespace hlr::stdlib
