// The shape generators of shapes.hpp: hand-derived vertex/edge/face counts, Euler characteristic,
// closedness, exact planarity of every face, outward orientation checked independently (the enclosed
// volume by the divergence theorem against the analytic volume, and every directed edge used once),
// the Platonic solids' dihedral angles, and rejection of bad arguments. Random inputs use fixed seeds.
#include "stdlib/shapes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/affine3.hpp"
#include "stdlib/generators.hpp"

namespace hlr::stdlib {
namespace {

constexpr double kPi = std::numbers::pi;

struct Counts {
  long v = 0, e = 0, f = 0, holes = 0;
  long euler() const { return v - e + f - holes; }
};

Counts counts(const Solid& s) {
  Counts c;
  c.v = static_cast<long>(s.vertices.size());
  c.f = static_cast<long>(s.faces.size());
  for (const auto& e : s.edges) c.e += e.kind != EdgeKind::Marking && e.kind != EdgeKind::Free;
  for (const auto& f : s.faces) c.holes += static_cast<long>(f.rings.size()) - 1;
  return c;
}

// V, E, F and holes as derived by hand, the Euler characteristic V − E + F − H they must give (2 for a
// closed genus-0 surface, 0 for genus 1, 1 for a disk), and whether the surface is closed.
void expect_counts(const Solid& s, Counts want, long euler, bool closed = true) {
  const Counts c = counts(s);
  EXPECT_EQ(s.closed, closed);
  EXPECT_EQ(c.v, want.v);
  EXPECT_EQ(c.e, want.e);
  EXPECT_EQ(c.f, want.f);
  EXPECT_EQ(c.holes, want.holes);
  EXPECT_EQ(c.euler(), euler);
}

long count_kind(const Solid& s, EdgeKind k) {
  return std::count_if(s.edges.begin(), s.edges.end(), [k](const SolidEdge& e) { return e.kind == k; });
}

// Divergence theorem over the rings' Newell normals: the enclosed volume, positive when faces point out.
double volume(const Solid& s) {
  double v = 0;
  for (const auto& f : s.faces)
    for (const auto& r : f.rings)
      v += dot(to_vector(s.vertices[r.vertices[0]]), newell_normal(s.vertices, r));
  return v / 6;
}

// Every face planar to rounding (far below the builder's 1e-6 tolerance): each vertex within 1e-10 of the
// face's size from the plane of its outer ring, recomputed here from Newell's normal.
void expect_planar(const Solid& s) {
  for (std::size_t i = 0; i < s.faces.size(); ++i) {
    const Ring& outer = s.faces[i].rings[0];
    const Vector3 n = normalize(newell_normal(s.vertices, outer));
    const Point3 o = s.vertices[outer.vertices[0]];
    double size = 0;
    for (VertexIndex a : outer.vertices)
      for (VertexIndex b : outer.vertices) size = std::max(size, distance(s.vertices[a], s.vertices[b]));
    for (const Ring& r : s.faces[i].rings)
      for (VertexIndex v : r.vertices)
        EXPECT_LE(std::abs(dot(n, s.vertices[v] - o)), 1e-10 * size) << "face " << i;
  }
}

// Consistent winding, checked from the faces alone: every directed edge is used at most once, and on a
// closed surface every edge is used once in each direction.
void expect_consistent_winding(const Solid& s) {
  std::map<std::pair<VertexIndex, VertexIndex>, int> used;
  for (const auto& f : s.faces)
    for (const auto& r : f.rings)
      for (std::size_t i = 0; i < r.vertices.size(); ++i)
        ++used[{r.vertices[i], r.vertices[(i + 1) % r.vertices.size()]}];
  for (const auto& [edge, n] : used) {
    EXPECT_EQ(n, 1) << edge.first << "-" << edge.second;
    if (s.closed) {
      EXPECT_TRUE(used.contains({edge.second, edge.first})) << edge.first << "-" << edge.second;
    }
  }
}

void expect_valid(const Solid& s) {
  expect_planar(s);
  expect_consistent_winding(s);
}

// Area of a regular n-gon of circumradius r.
double ngon_area(int n, double r) { return 0.5 * n * r * r * std::sin(2 * kPi / n); }

// Deterministic values in [0, 1) (splitmix64), identical on every platform.
double unit_hash(std::uint64_t seed, std::uint64_t i) {
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ULL + i;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return static_cast<double>((z ^ (z >> 31)) >> 11) / static_cast<double>(1ULL << 53);
}

template <typename F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no std::invalid_argument)";
}

// `call` throws std::invalid_argument with exactly `text` (a macro keeps each case on one line).
#define EXPECT_INVALID(call, text) EXPECT_EQ(message_of([&] { call; }), text)

// ---- polygon checks ----------------------------------------------------------------------------------

TEST(ShapeChecks, FindsCrossingsTouchesAndZeroEdges) {
  const std::vector<Point2> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_FALSE(find_ring_defect({square}));
  EXPECT_FALSE(find_ring_defect({square, {{0.5, 0.5}, {0.5, 1.5}, {1.5, 1.5}, {1.5, 0.5}}}));
  // A bow tie: edges 0–1 and 2–3 cross.
  const auto bow = find_ring_defect({{{0, 0}, {2, 2}, {2, 0}, {0, 2}}});
  ASSERT_TRUE(bow);
  EXPECT_EQ(bow->edge_a, 0u);
  EXPECT_EQ(bow->edge_b, 2u);
  // A hole touching the outline at a vertex, a repeated point, a spike folding back on itself.
  EXPECT_TRUE(find_ring_defect({square, {{1, 1}, {2, 1}, {1, 1.5}}}));
  EXPECT_TRUE(find_ring_defect({{{0, 0}, {1, 0}, {1, 0}, {0, 1}}}));
  EXPECT_TRUE(find_ring_defect({{{0, 0}, {2, 0}, {1, 0}, {1, 1}}}));
  // Open polylines: the closing edge does not exist.
  EXPECT_FALSE(find_ring_defect({{{0, 0}, {2, 2}, {2, 0}}}, false));
  EXPECT_TRUE(find_ring_defect({{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}, false));
  EXPECT_FALSE(find_ring_defect({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, false));
  const std::vector<std::vector<Point2>> crossing = {square, {{1, 1}, {3, 1}, {3, 1.5}}};
  const auto d = find_ring_defect(crossing);
  ASSERT_TRUE(d);
  EXPECT_EQ(describe_ring_defect(*d, {"outline", "hole 0"}, crossing),
            "hole 0 crosses or touches outline (edge 0\u20131 of hole 0, edge 1\u20132 of outline)");
}

// ---- pyramid -------------------------------------------------------------------------------------------

TEST(ShapePyramid, SquarePyramidCountsAndVolume) {
  const std::vector<Point3> base = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  for (bool reversed : {false, true})
    for (double apex_z : {3.0, -3.0}) {
      SCOPED_TRACE(std::to_string(reversed) + " " + std::to_string(apex_z));
      std::vector<Point3> outline = base;
      if (reversed) std::reverse(outline.begin(), outline.end());
      const Solid s = pyramid(outline, {0.5, 3, apex_z});  // oblique: apex outside the base's shadow
      expect_counts(s, {5, 8, 5}, 2);
      EXPECT_NEAR(volume(s), 4 * 3 / 3.0, 1e-12);
      expect_valid(s);
    }
}

TEST(ShapePyramid, NonConvexTiltedOutline) {
  // An L (area 3) in a tilted plane; the apex 2 above the plane along its normal, then shifted sideways.
  const Affine3 place = Affine3::rotation(normalize({1, 2, 3}), 0.7).then(Affine3::translation({5, -1, 2}));
  std::vector<Point3> outline;
  for (Point2 p : std::vector<Point2>{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})
    outline.push_back(place.apply(Point3{p.x, p.y, 0}));
  const Point3 apex = place.apply(Point3{3, -1, 2});
  const Solid s = pyramid(outline, apex);
  expect_counts(s, {7, 12, 7}, 2);
  EXPECT_NEAR(volume(s), 3 * 2 / 3.0, 1e-9);
  for (std::size_t i = 0; i < outline.size(); ++i)
    EXPECT_TRUE(s.vertices[i] == outline[i] || s.vertices[5 - i] == outline[i]);
  expect_valid(s);
}

TEST(ShapePyramid, BadArguments) {
  const std::vector<Point3> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_INVALID(pyramid(square, {0.5, 0.5, 0}), "pyramid(): apex must lie off the outline's plane");
  EXPECT_INVALID(pyramid({{0, 0, 0}, {1, 0, 0}}, {0, 0, 1}), "pyramid(): outline needs at least 3 points");
  EXPECT_THROW(pyramid({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {0, 0, 1}), std::invalid_argument);  // collinear
  EXPECT_THROW(pyramid({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 0, 1}),
               std::invalid_argument);  // bow tie
  EXPECT_INVALID(pyramid({{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}}, {0, 0, 1}),
                 "pyramid(): outline is not planar");
  EXPECT_THROW(pyramid(square, {0, 0, NAN}), std::invalid_argument);
  // A repeated closing point is not an error.
  std::vector<Point3> closed = square;
  closed.push_back(square[0]);
  EXPECT_EQ(counts(pyramid(closed, {0, 0, 1})).v, 5);
}

// ---- Platonic solids -------------------------------------------------------------------------------------

struct PlatonicCase {
  const char* name;
  std::function<Solid(double)> make;
  long v, e, f;
  std::size_t sides;     // corners per face
  double dihedral;       // interior dihedral angle
  double volume_per_r3;  // volume for circumradius 1
};

std::vector<PlatonicCase> platonic_cases() {
  const double s5 = std::sqrt(5.0);
  const double a_tet = std::sqrt(8.0 / 3), a_cube = 2 / std::sqrt(3.0);
  const double a_dod = 4 / (std::sqrt(3.0) * (1 + s5)), a_ico = 4 / std::sqrt(10 + 2 * s5);
  return {
      {"tetrahedron", tetrahedron, 4, 6, 4, 3, std::acos(1.0 / 3), std::pow(a_tet, 3) / (6 * std::sqrt(2.0))},
      {"hexahedron", hexahedron, 8, 12, 6, 4, kPi / 2, std::pow(a_cube, 3)},
      {"octahedron", octahedron, 6, 12, 8, 3, std::acos(-1.0 / 3), 4.0 / 3},
      {"dodecahedron", dodecahedron, 20, 30, 12, 5, std::acos(-1 / s5),
       (15 + 7 * s5) / 4 * std::pow(a_dod, 3)},
      {"icosahedron", icosahedron, 12, 30, 20, 3, std::acos(-s5 / 3), 5 * (3 + s5) / 12 * std::pow(a_ico, 3)},
  };
}

TEST(ShapePlatonic, CountsVolumesAndDihedralAngles) {
  const double r = 1.7;
  for (const PlatonicCase& pc : platonic_cases()) {
    SCOPED_TRACE(pc.name);
    const Solid s = pc.make(r);
    expect_counts(s, {pc.v, pc.e, pc.f}, 2);
    EXPECT_NEAR(volume(s), pc.volume_per_r3 * r * r * r, 1e-12 * r * r * r);
    for (const Point3& p : s.vertices) EXPECT_NEAR(length(to_vector(p)), r, 1e-12);
    for (const Face& f : s.faces) EXPECT_EQ(f.rings[0].vertices.size(), pc.sides);
    // Every edge a convex Feature edge; the outward normals differ by π minus the dihedral angle.
    EXPECT_EQ(count_kind(s, EdgeKind::Feature), pc.e);
    for (const SolidEdge& e : s.edges) {
      EXPECT_FALSE(e.concave);
      const Vector3 nl = s.planes[static_cast<std::size_t>(e.left)].normal;
      const Vector3 nr = s.planes[static_cast<std::size_t>(e.right)].normal;
      EXPECT_NEAR(std::acos(std::clamp(dot(nl, nr), -1.0, 1.0)), kPi - pc.dihedral, 1e-9);
    }
    expect_valid(s);
  }
}

TEST(ShapePlatonic, BadRadius) {
  for (const PlatonicCase& pc : platonic_cases()) {
    EXPECT_INVALID(pc.make(0), std::string(pc.name) + "(): r must be positive");
    EXPECT_THROW(pc.make(-1), std::invalid_argument);
    EXPECT_THROW(pc.make(NAN), std::invalid_argument);
    EXPECT_THROW(pc.make(INFINITY), std::invalid_argument);
  }
}

// ---- cone ------------------------------------------------------------------------------------------------

TEST(ShapeCone, ConeAndFrustum) {
  const Solid c = cone(2, 3, 0, 12, 0);
  expect_counts(c, {13, 24, 13}, 2);
  EXPECT_NEAR(volume(c), ngon_area(12, 2) * 3 / 3, 1e-12);
  EXPECT_EQ(count_kind(c, EdgeKind::Feature), 24);
  EXPECT_NEAR(c.vertices[0].x, 2, 0);  // the first corner on +x, as cylinder()'s
  expect_valid(c);

  const Solid f = cone(2, 3, 1, 12, 40);  // 30° between side faces < 40° crease: side edges Smooth
  expect_counts(f, {24, 36, 14}, 2);
  const double a1 = ngon_area(12, 2), a2 = ngon_area(12, 1);
  EXPECT_NEAR(volume(f), 3.0 / 3 * (a1 + a2 + std::sqrt(a1 * a2)), 1e-12);
  EXPECT_EQ(count_kind(f, EdgeKind::Smooth), 12);
  EXPECT_EQ(count_kind(f, EdgeKind::Feature), 24);
  expect_valid(f);

  const Solid up = cone(0, 2, 1, 8, 0);  // upside down: apex at the origin
  expect_counts(up, {9, 16, 9}, 2);
  EXPECT_NEAR(volume(up), ngon_area(8, 1) * 2 / 3, 1e-12);
  expect_valid(up);
}

TEST(ShapeCone, BadArguments) {
  EXPECT_INVALID(cone(1, 1, 0, 2, 0), "cone(): sides must be at least 3");
  EXPECT_INVALID(cone(-1, 1, 0, 8, 0), "cone(): r must not be negative");
  EXPECT_INVALID(cone(1, 0, 0, 8, 0), "cone(): h must be positive");
  EXPECT_INVALID(cone(1, 1, -1, 8, 0), "cone(): top must not be negative");
  EXPECT_INVALID(cone(0, 1, 0, 8, 0), "cone(): r and top must not both be 0");
  EXPECT_THROW(cone(NAN, 1, 0, 8, 0), std::invalid_argument);
  EXPECT_THROW(cone(1, INFINITY, 0, 8, 0), std::invalid_argument);
  EXPECT_THROW(cone(1, 1, 0, 8, -5), std::invalid_argument);
}

// ---- revolve ---------------------------------------------------------------------------------------------

TEST(ShapeRevolve, RectangleIsARegularPrism) {
  const Solid s = revolve({{0, 0}, {1, 0}, {1, 2}, {0, 2}}, 16, 360, 0);
  expect_counts(s, {32, 48, 18}, 2);  // the poles border only the flat disks: no pole vertices
  EXPECT_NEAR(volume(s), ngon_area(16, 1) * 2, 1e-12);
  expect_valid(s);
  // The same corners as cylinder().
  const Solid cyl = cylinder({0, 0, 0}, 1, 2, 16, 0);
  for (const Point3& p : s.vertices)
    EXPECT_TRUE(std::any_of(cyl.vertices.begin(), cyl.vertices.end(),
                            [&](Point3 q) { return distance(p, q) < 1e-12; }));
  // Given as a closed loop (first == last, along the axis) it is the same solid.
  const Solid loop = revolve({{0, 2}, {0, 0}, {1, 0}, {1, 2}, {0, 2}}, 16, 360, 0);
  expect_counts(loop, {32, 48, 18}, 2);
  EXPECT_NEAR(volume(loop), ngon_area(16, 1) * 2, 1e-12);
}

TEST(ShapeRevolve, WasherIsAClosedRingWithAnnuli) {
  const int n = 10;
  const Solid s = revolve({{1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 0}}, n, 360, 0);
  expect_counts(s, {4 * n, 6 * n, 2 * n + 2, 2}, 0);  // genus 1
  EXPECT_NEAR(volume(s), ngon_area(n, 2) - ngon_area(n, 1), 1e-12);
  // Clockwise, the profile gives the same solid.
  EXPECT_NEAR(volume(revolve({{1, 0}, {1, 1}, {2, 1}, {2, 0}, {1, 0}}, n, 360, 0)), volume(s), 1e-12);
  expect_valid(s);
}

TEST(ShapeRevolve, SemicircleMatchesSphere) {
  const int slices = 12, stacks = 8;
  std::vector<Point2> profile;
  for (int i = 0; i <= stacks; ++i) {
    const double theta = kPi * i / stacks;
    profile.push_back({i == 0 || i == stacks ? 0 : std::sin(theta), -std::cos(theta)});
  }
  const Solid s = revolve(profile, slices, 360, 0);
  expect_counts(s, {slices * (stacks - 1) + 2, slices * (2 * stacks - 1), slices * stacks}, 2);
  EXPECT_NEAR(volume(s), volume(sphere({0, 0, 0}, 1, slices, stacks, 0)), 1e-12);
  expect_valid(s);
}

TEST(ShapeRevolve, SlantedSegmentsGivePlanarTrapezoids) {
  // A vase: slanted segments in both directions, a flat bottom disk and a pole at the top.
  const Solid s = revolve({{0, 0}, {2, 0.5}, {1, 1.5}, {1.5, 2.5}, {0.4, 2.5}, {0, 3}}, 24, 360, 30);
  // 4 rings + 2 poles; 24 triangles at each pole, 2 bands of quads, the flat annulus at z = 2.5 (a hole);
  // edges: 4 rings, 4 sets of 24 meridians.
  expect_counts(s, {4 * 24 + 2, 4 * 24 + 4 * 24, 24 * 2 + 24 * 2 + 1, 1}, 2);
  EXPECT_GT(volume(s), 0);
  expect_valid(s);
}

TEST(ShapeRevolve, PartialAngleIsAWedge) {
  const Solid s = revolve({{0, 0}, {1, 0}, {1, 2}, {0, 2}}, 4, 90, 0);
  expect_counts(s, {12, 18, 8}, 2);
  EXPECT_NEAR(volume(s), 2 * (4 * 0.5 * std::sin(kPi / 8)), 1e-12);
  expect_valid(s);
  // The end face lies in the half-plane at 90°.
  for (const Point3& p : s.vertices) EXPECT_TRUE(p.x >= -1e-15 && p.y >= -1e-15);

  const Solid half = revolve({{1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 0}}, 6, 180, 0);
  expect_counts(half, {28, 42, 16}, 2);
  EXPECT_NEAR(volume(half), 6 * 0.5 * std::sin(kPi / 6) * (4 - 1), 1e-12);
  expect_valid(half);
  // More than 180°: non-convex, still closed and outward.
  const Solid big = revolve({{0, 0}, {1, 0}, {1, 2}, {0, 2}}, 9, 270, 0);
  expect_counts(big, {2 * 10 + 2, 2 * 9 + 10 + 4 + 1, 2 + 9 + 2}, 2);  // arcs, walls, spokes, axis edge
  EXPECT_NEAR(volume(big), 2 * 9 * 0.5 * std::sin(kPi * 1.5 / 9), 1e-12);
  expect_valid(big);
}

TEST(ShapeRevolve, OpenProfilesGiveOpenSurfaces) {
  const int n = 8;
  const Solid tube = revolve({{1, 0}, {1, 1}}, n, 360, 0);
  expect_counts(tube, {2 * n, 3 * n, n}, 0, false);  // an annulus
  EXPECT_EQ(count_kind(tube, EdgeKind::Boundary), 2 * n);
  // Outside on the right of the profile's direction: going up at r = 1, the quads face away from the axis.
  for (std::size_t i = 0; i < tube.faces.size(); ++i) {
    const Point3 p = tube.vertices[tube.faces[i].rings[0].vertices[0]];
    EXPECT_GT(dot(tube.planes[i].normal, Vector3{p.x, p.y, 0}), 0);
  }
  expect_valid(tube);

  const Solid bowl = revolve({{0, 0}, {1, 0}, {1, 1}}, n, 360, 0);  // flat bottom, open top
  expect_counts(bowl, {2 * n, 3 * n, n + 1}, 1, false);             // a disk
  EXPECT_EQ(count_kind(bowl, EdgeKind::Boundary), n);
  EXPECT_LT(bowl.planes[0].normal.z, 0);  // the bottom faces down
  expect_valid(bowl);

  const Solid sheet = revolve({{1, 0}, {1, 1}, {2, 1}}, 3, 90, 0);  // partial: no profile faces
  EXPECT_FALSE(sheet.closed);
  EXPECT_EQ(counts(sheet).f, 3 + 1);
  expect_valid(sheet);
  // Leading runs of axis points are trimmed.
  EXPECT_EQ(counts(revolve({{0, -1}, {0, 0}, {1, 0}, {1, 1}}, n, 360, 0)).f, n + 1);
}

TEST(ShapeRevolve, BadArguments) {
  const std::vector<Point2> rect = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_INVALID(revolve(rect, 2, 360, 0), "revolve(): segments must be at least 3");
  EXPECT_INVALID(revolve(rect, 1, 180, 0), "revolve(): segments must be more than angle / 180");
  EXPECT_THROW(revolve(rect, 8, 0, 0), std::invalid_argument);
  EXPECT_THROW(revolve(rect, 8, 400, 0), std::invalid_argument);
  EXPECT_THROW(revolve(rect, 8, NAN, 0), std::invalid_argument);
  EXPECT_THROW(revolve(rect, 8, 360, -1), std::invalid_argument);
  EXPECT_INVALID(revolve({{0, 0}, {-1, 0}, {0, 1}}, 8, 360, 0),
                 "revolve(): profile points need r \u2265 0 (got (-1, 0))");
  EXPECT_INVALID(revolve({{0, 0}}, 8, 360, 0), "revolve(): profile needs at least 2 points");
  EXPECT_INVALID(revolve({{0, 0}, {0, 1}}, 8, 360, 0), "revolve(): profile lies on the axis");
  // Self-intersecting, pinching at an inner axis point, or touching the axis at a single point.
  EXPECT_THROW(revolve({{0, 0}, {2, 2}, {2, 0}, {0, 2}}, 8, 360, 0), std::invalid_argument);
  EXPECT_THROW(revolve({{0, 0}, {1, 1}, {0, 2}, {1, 3}, {0, 4}}, 8, 360, 0), std::invalid_argument);
  EXPECT_THROW(revolve({{0, 0}, {1, -1}, {1, 1}, {0, 0}}, 8, 360, 0), std::invalid_argument);
  EXPECT_THROW(revolve({{1, 0}, {2, 0}, {2, 1}, {1, 0}, {1, 1}, {1, 0}}, 8, 360, 0), std::invalid_argument);
  EXPECT_THROW(revolve({{0, 0}, {1e-12, 0.5}, {1, 1}}, 8, 360, 0),
               std::invalid_argument);  // too near the axis
}

// ---- extrude ---------------------------------------------------------------------------------------------

TEST(ShapeExtrude, TiltedNonConvexOutlineWithHoleAnyOrientation) {
  // An L (area 6) with a hole (area 0.5) in a tilted plane, swept along an oblique vector. Concave edges:
  // the L's inner corner and the hole's four corners.
  const Affine3 place =
      Affine3::rotation(normalize({1, -2, 0.5}), 1.1).then(Affine3::translation({3, 4, -2}));
  auto lift = [&](const std::vector<Point2>& ring) {
    std::vector<Point3> r;
    for (Point2 p : ring) r.push_back(place.apply(Point3{p.x, p.y, 0}));
    return r;
  };
  const std::vector<Point3> outline = lift({{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}});  // area 6
  const std::vector<Point3> hole = lift({{2, 0.25}, {3, 0.25}, {3, 0.75}, {2, 0.75}});         // area 0.5
  const Vector3 normal = place.apply(Vector3{0, 0, 1});
  const Vector3 along = place.apply(Vector3{0.7, -0.4, 2.5});  // 2.5 across the plane
  for (bool flip_outline : {false, true})
    for (bool flip_hole : {false, true})
      for (double sign : {1.0, -1.0}) {
        SCOPED_TRACE(std::to_string(flip_outline) + std::to_string(flip_hole) + std::to_string(sign));
        std::vector<Point3> o = outline, h = hole;
        if (flip_outline) std::reverse(o.begin(), o.end());
        if (flip_hole) std::reverse(h.begin(), h.end());
        const Solid s = extrude(o, sign * along, {h});
        expect_counts(s, {20, 30, 12, 2}, 0);
        EXPECT_NEAR(volume(s), (6 - 0.5) * std::abs(dot(sign * along, normal)), 1e-9);
        // The input points are the base's vertices, unchanged.
        for (const Point3& p : o)
          EXPECT_TRUE(std::find(s.vertices.begin(), s.vertices.end(), p) != s.vertices.end());
        EXPECT_EQ(std::count_if(s.edges.begin(), s.edges.end(), [](const SolidEdge& e) { return e.concave; }),
                  5);
        expect_valid(s);
      }
}

TEST(ShapeExtrude, RandomStarPolygonsSeeded) {
  // Star-shaped polygons (random radii at increasing angles) are simple; extrude and pyramid must give
  // the shoelace area times the height (and a third of it).
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(seed);
    const int n = 3 + static_cast<int>(unit_hash(seed, 0) * 20);
    std::vector<Point3> outline;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * kPi * (i + 0.8 * unit_hash(seed, 2 * i + 1)) / n,
                   r = 0.3 + unit_hash(seed, 2 * i + 2);
      outline.push_back({r * std::cos(a), r * std::sin(a), 1.5});
    }
    double area = 0;
    for (int i = 0; i < n; ++i) {
      const Point3 p = outline[i], q = outline[(i + 1) % n];
      area += 0.5 * (p.x * q.y - q.x * p.y);
    }
    const Solid e = extrude(outline, {0.3, 0.2, -2});
    EXPECT_NEAR(volume(e), std::abs(area) * 2, 1e-12);
    EXPECT_EQ(counts(e).f, n + 2);
    expect_valid(e);
    const Solid p = pyramid(outline, {0.1, -0.2, 4.5});
    EXPECT_NEAR(volume(p), std::abs(area) * 3 / 3, 1e-12);
    expect_valid(p);
  }
}

TEST(ShapeExtrude, BadArguments) {
  const std::vector<Point3> square = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  EXPECT_INVALID(extrude(square, {1, 1, 0}),
                 "extrude(): direction v must not be parallel to the outline's plane");
  EXPECT_INVALID(extrude(square, {0, 0, 0}), "extrude(): direction v must not be zero");
  EXPECT_THROW(extrude(square, {0, 0, NAN}), std::invalid_argument);
  EXPECT_INVALID(extrude(square, {0, 0, 1}, {{{3, 3, 0}, {4, 3, 0}, {4, 4, 0}}}),
                 "extrude(): hole 0 is not inside the outline");
  EXPECT_INVALID(
      extrude(square, {0, 0, 1}, {{{1, 1, 0}, {3, 1, 0}, {1, 1.5, 0}}}),
      "extrude(): hole 0 crosses or touches outline (edge 0\u20131 of hole 0, edge 1\u20132 of outline)");
  EXPECT_INVALID(extrude(square, {0, 0, 1}, {{{0.5, 0.5, 0.5}, {1, 0.5, 0}, {1, 1, 0}}}),
                 "extrude(): hole 0 is not in the outline's plane");
  EXPECT_INVALID(extrude({{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 3, 0}}, {0, 0, 1}),
                 "extrude(): outline is not simple: its edges 0\u20131 and 2\u20133 cross or touch");
  EXPECT_INVALID(extrude({{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}}, {0, 0, 1}),
                 "extrude(): outline has zero area (its points are collinear, or it crosses itself)");
  EXPECT_THROW(
      extrude(square, {0, 0, 1},
              {{{0.2, 0.2, 0}, {1.8, 0.2, 0}, {1.8, 1.8, 0}}, {{1.5, 0.5, 0}, {1.6, 0.5, 0}, {1.6, 0.6, 0}}}),
      std::invalid_argument);  // a hole inside another hole
}

// ---- sweep -----------------------------------------------------------------------------------------------

TEST(ShapeSweep, SquareAlongAnLPath) {
  const std::vector<Point2> square = {{-0.25, -0.25}, {0.25, -0.25}, {0.25, 0.25}, {-0.25, 0.25}};
  const Solid s = sweep(square, {{0, 0, 0}, {4, 0, 0}, {4, 3, 0}}, 0);
  expect_counts(s, {12, 20, 10}, 2);
  // A prism cut by planes through its centroid line keeps area × length: the path's length is 7.
  EXPECT_NEAR(volume(s), 0.25 * 7, 1e-12);
  // The mitre section at the corner lies in the bisecting plane x − y = 4 − 0 (through (4, 0)).
  for (std::size_t k = 4; k < 8; ++k) EXPECT_NEAR(s.vertices[k].x + s.vertices[k].y, 4, 1e-12);
  EXPECT_EQ(std::count_if(s.edges.begin(), s.edges.end(), [](const SolidEdge& e) { return e.concave; }), 1);
  expect_valid(s);
  // Start frame: along +x, profile x → world +y and profile y → world +z.
  EXPECT_NEAR(distance(s.vertices[0], {0, -0.25, -0.25}), 0, 1e-15);
  EXPECT_NEAR(distance(s.vertices[1], {0, 0.25, -0.25}), 0, 1e-15);
  // Along +z the profile keeps its orientation; a clockwise profile is reoriented.
  const Solid up = sweep({{0, 0}, {0, 1}, {2, 1}, {2, 0}}, {{5, 5, 0}, {5, 5, 3}}, 0);
  EXPECT_NEAR(volume(up), 6, 1e-12);
  for (const Point3& p : up.vertices) EXPECT_TRUE(p.x >= 5 && p.x <= 7 && p.y >= 5 && p.y <= 6);
}

TEST(ShapeSweep, NonPlanarPathKeepsFacesPlanar) {
  // A triangle centred on its centroid along a twisting polyline: every side quad must stay planar.
  const std::vector<Point2> tri = {{-1, -1}, {2, -1}, {-1, 2}};  // area 4.5, centroid at the origin
  const std::vector<Point3> path = {{0, 0, 0}, {8, 0, 0}, {8, 8, 3}, {0, 9, 8}, {0, 0, 12}, {5, -3, 20}};
  const Solid s = sweep(tri, path, 0);
  expect_counts(s, {3 * 6, 3 * 6 + 3 * 5, 3 * 5 + 2}, 2);
  double total = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) total += distance(path[i], path[i + 1]);
  EXPECT_NEAR(volume(s), 4.5 * total, 1e-9);
  expect_valid(s);
}

TEST(ShapeSweep, ClosedPlanarPathIsARing) {
  const std::vector<Point2> square = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  // A tilted square loop (planar), so the frame returns to itself.
  const Affine3 tilt = Affine3::rotation(normalize({1, 1, 0}), 0.6);
  std::vector<Point3> path;
  for (Point3 p : std::vector<Point3>{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {0, 0, 0}})
    path.push_back(tilt.apply(p));
  const Solid s = sweep(square, path, 0);
  expect_counts(s, {16, 32, 16}, 0);  // genus 1
  EXPECT_NEAR(volume(s), 1 * 16, 1e-9);
  expect_valid(s);
  // Either direction round the loop is outward.
  std::reverse(path.begin(), path.end());
  EXPECT_NEAR(volume(sweep(square, path, 0)), 16, 1e-9);
}

TEST(ShapeSweep, BadArguments) {
  const std::vector<Point2> sq = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  EXPECT_INVALID(sweep(sq, {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}}, 0),
                 "sweep(): path has a zero-length segment at point 1");
  EXPECT_INVALID(sweep(sq, {{0, 0, 0}, {2, 0, 0}, {1, 0, 0}}, 0), "sweep(): path reverses at point 1");
  EXPECT_INVALID(sweep(sq, {{0, 0, 0}}, 0), "sweep(): path needs at least 2 points");
  EXPECT_INVALID(sweep(sq, {{0, 0, 0}, {3, 0, 0}, {0, 0.3, 0}}, 0),
                 "sweep(): path segment 0\u20131 is too short for the profile at its corners: the mitred "
                 "ends would cross");
  EXPECT_THROW(sweep({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, {{0, 0, 0}, {0, 0, 1}}, 0), std::invalid_argument);
  EXPECT_THROW(sweep({{0, 0}, {1, 1}}, {{0, 0, 0}, {0, 0, 1}}, 0), std::invalid_argument);
  EXPECT_THROW(sweep(sq, {{0, 0, 0}, {0, 0, NAN}}, 0), std::invalid_argument);
  // A closed path that is not planar twists the frame round the loop.
  const std::string twisted = message_of([&] {
    sweep(sq, {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {4, 4, 4}, {0, 0, 0}}, 0);
  });
  EXPECT_NE(twisted.find("twists the profile"), std::string::npos) << twisted;
}

// ---- heightfield -----------------------------------------------------------------------------------------

// Volume above `base` of the surface with cells split along (i, j)–(i + 1, j + 1), independently of faces.
double terrain_volume(const std::vector<std::vector<double>>& h, double dx, double dy, double base) {
  double v = 0;
  for (std::size_t i = 0; i + 1 < h.size(); ++i)
    for (std::size_t j = 0; j + 1 < h[i].size(); ++j)
      v += dx * dy * ((2 * h[i][j] + h[i][j + 1] + 2 * h[i + 1][j + 1] + h[i + 1][j]) / 6 - base);
  return v;
}

TEST(ShapeHeightfield, RandomTerrainOpenAndBlock) {
  std::vector<std::vector<double>> h(3, std::vector<double>(4));
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 4; ++j) h[i][j] = 1 + unit_hash(7, i * 4 + j);
  const Solid open = heightfield(h, 0.5, 0.75, std::nullopt, 0);
  // 6 warped cells, two triangles each; edges along x, along y and the diagonals; a disk.
  expect_counts(open, {12, 9 + 8 + 6, 12}, 1, false);
  EXPECT_EQ(count_kind(open, EdgeKind::Boundary), 2 * 3 + 2 * 2);
  for (const Plane& p : open.planes) EXPECT_GT(p.normal.z, 0);
  expect_valid(open);

  const Solid block = heightfield(h, 0.5, 0.75, -0.5, 0);
  expect_counts(block, {16, 23 + 4 + 4, 12 + 5}, 2);  // plus the wall corners and the bottom's edges
  EXPECT_NEAR(volume(block), terrain_volume(h, 0.5, 0.75, -0.5), 1e-12);
  expect_valid(block);
}

TEST(ShapeHeightfield, PlanarCellsStayQuads) {
  // h = 1 + 0.5x + 0.25y: every cell planar, so 2 × 3 quads; with a step in one column, only the cells
  // next to it split.
  std::vector<std::vector<double>> h(3, std::vector<double>(4));
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 4; ++j)
      h[i][j] = 1 + 0.5 * static_cast<double>(j) + 0.25 * static_cast<double>(i);
  const Solid s = heightfield(h, 1, 1, 0, 30);
  expect_counts(s, {12 + 4, 17 + 4 + 4, 6 + 5}, 2);  // grid edges, wall corners and bottom edges
  EXPECT_NEAR(volume(s), 3 * 2 * (1 + 0.5 * 1.5 + 0.25 * 1), 1e-12);
  EXPECT_EQ(count_kind(s, EdgeKind::Flat), 7);  // between the coplanar quads
  expect_valid(s);
  h[1][3] += 1;
  const Solid bumped = heightfield(h, 1, 1, 0, 30);
  EXPECT_EQ(counts(bumped).f, 4 + 2 * 2 + 5);
  EXPECT_NEAR(volume(bumped), terrain_volume(h, 1, 1, 0), 1e-12);
  expect_valid(bumped);
}

TEST(ShapeHeightfield, BadArguments) {
  const std::vector<std::vector<double>> ok = {{0, 1}, {1, 2}};
  EXPECT_INVALID(heightfield({{0, 1}}, 1, 1, std::nullopt, 0), "heightfield(): values need at least 2 rows");
  EXPECT_INVALID(heightfield({{0, 1}, {1}}, 1, 1, std::nullopt, 0),
                 "heightfield(): row 1 of values has 1 heights, row 0 has 2; rows must be equally long");
  EXPECT_INVALID(heightfield(ok, 0, 1, std::nullopt, 0), "heightfield(): dx must be positive");
  EXPECT_INVALID(heightfield(ok, 1, -1, std::nullopt, 0), "heightfield(): dy must be positive");
  EXPECT_INVALID(heightfield(ok, 1, 1, 0, 0), "heightfield(): base must be below every height");
  EXPECT_THROW(heightfield({{0, NAN}, {1, 2}}, 1, 1, std::nullopt, 0), std::invalid_argument);
  EXPECT_THROW(heightfield(ok, 1, 1, NAN, 0), std::invalid_argument);
  EXPECT_THROW(heightfield({{0}, {1}}, 1, 1, std::nullopt, 0), std::invalid_argument);
}

}  // namespace
}  // namespace hlr::stdlib
