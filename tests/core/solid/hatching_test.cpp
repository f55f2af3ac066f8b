// Hatch lines on faces (core/solid/hatching.hpp), checked by hand on boxes and prisms: where the lines lie,
// where they stop, which faces get which tone, and that coplanar faces share lines end to end.
//   hlr_core_tests --gtest_filter='Hatching*'
#include "core/solid/hatching.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

#include "stdlib/generators.hpp"
#include "tests/core/solid/solid_test_helpers.hpp"
#include "tests/support/mesh_views.hpp"

namespace hlr::test {
namespace {

namespace gen = hlr::stdlib;

struct HatchLine {
  Point3 a, b;
  FaceIndex face;
};

// The hatch edges of `s`, each as its two end points and its face.
std::vector<HatchLine> hatch_lines(const Solid& s) {
  std::vector<HatchLine> out;
  for (const SolidEdge& e : s.edges)
    if (e.kind == EdgeKind::Hatch) out.push_back({s.vertices[e.v0], s.vertices[e.v1], e.left});
  return out;
}

// Which face of a box faces along `n`.
FaceIndex face_facing(const Solid& s, Vector3 n) {
  for (std::size_t f = 0; f < s.planes.size(); ++f)
    if (dot(s.planes[f].normal, n) > 0.999) return static_cast<FaceIndex>(f);
  return kNoFace;
}

// Every end point of the hatch lines, exactly, and how many lines end there.
std::map<std::tuple<double, double, double>, int> line_ends(const std::vector<HatchLine>& lines) {
  std::map<std::tuple<double, double, double>, int> ends;
  for (const HatchLine& l : lines)
    for (const Point3 p : {l.a, l.b}) ++ends[{p.x, p.y, p.z}];
  return ends;
}

TEST(Hatching, UnitBoxQuarterApartByHand) {
  // Spacing 0.25, offset half of it: on every face the lines lie at 0.125, 0.375, 0.625 and 0.875 across it,
  // from edge to edge. The top face's horizontal is x (it faces straight up), so at angle 0 its lines run
  // along x at those y.
  const Solid box = gen::box({0, 0, 0}, {1, 1, 1});
  HatchSpec spec;
  spec.spacing = 0.25;
  spec.angle_deg = 0;
  const Solid h = hatched(box, spec);
  solid_test::expect_valid_solid(h);
  const auto lines = hatch_lines(h);
  ASSERT_EQ(lines.size(), 24u);  // 4 a face
  const FaceIndex top = face_facing(h, {0, 0, 1});
  std::set<double> ys;
  for (const HatchLine& l : lines) {
    if (l.face != top) continue;
    EXPECT_DOUBLE_EQ(l.a.z, 1);
    EXPECT_DOUBLE_EQ(l.b.z, 1);
    EXPECT_DOUBLE_EQ(l.a.y, l.b.y);
    EXPECT_DOUBLE_EQ(std::min(l.a.x, l.b.x), 0);
    EXPECT_DOUBLE_EQ(std::max(l.a.x, l.b.x), 1);
    ys.insert(l.a.y);
  }
  EXPECT_EQ(ys, (std::set<double>{0.125, 0.375, 0.625, 0.875}));
  // The wall facing −y: its horizontal is z × n = x, its up is z; at angle 90 the lines stand upright,
  // at x = 0.125 … 0.875.
  spec.angle_deg = 90;
  const FaceIndex front = face_facing(box, {0, -1, 0});
  std::set<double> xs;
  for (const HatchLine& l : hatch_lines(hatched(box, spec))) {
    if (l.face != front) continue;
    EXPECT_NEAR(l.a.x, l.b.x, 1e-15);
    EXPECT_NEAR(std::abs(l.a.z - l.b.z), 1, 1e-15);
    xs.insert(std::round(l.a.x * 1000) / 1000);
  }
  EXPECT_EQ(xs, (std::set<double>{0.125, 0.375, 0.625, 0.875}));
}

TEST(Hatching, OnlyTheFacesInThePlaneWhenOneIsGiven) {
  // A section's cut faces: of a unit box only the top, z = 1 facing up, lies in the plane z − 1 = 0 with
  // normal +z; the bottom is parallel but elsewhere, the walls are across it.
  const Solid box = gen::box({0, 0, 0}, {1, 1, 1});
  HatchSpec spec;
  spec.spacing = 0.25;
  spec.angle_deg = 0;
  spec.only_in_plane = Plane{{0, 0, 1}, -1};
  spec.in_plane_tolerance = 1e-12;
  const Solid h = hatched(box, spec);
  const auto lines = hatch_lines(h);
  ASSERT_EQ(lines.size(), 4u);
  for (const HatchLine& l : lines) EXPECT_EQ(l.face, face_facing(h, {0, 0, 1}));
  EXPECT_EQ(hatch_line_bound(box, spec), 4u);
  // The same plane facing down matches no face (the top faces up); off by more than the tolerance, none.
  spec.only_in_plane = Plane{{0, 0, -1}, 1};
  EXPECT_TRUE(hatch_lines(hatched(box, spec)).empty());
  spec.only_in_plane = Plane{{0, 0, 1}, -1 - 1e-9};
  EXPECT_TRUE(hatch_lines(hatched(box, spec)).empty());
}

TEST(Hatching, DiagonalLinesStopAtTheFacesEdges) {
  // At 45° on the top face of a 2 × 1 box, spacing √2/4 across: each line x − y = c runs between two
  // points of the outline, and its length is what the outline leaves of it.
  const Solid box = gen::box({0, 0, 0}, {2, 1, 1});
  HatchSpec spec;
  spec.spacing = std::sqrt(2.0) / 4;
  spec.angle_deg = 45;
  const FaceIndex top = face_facing(box, {0, 0, 1});
  double total = 0;
  int count = 0;
  for (const HatchLine& l : hatch_lines(hatched(box, spec))) {
    if (l.face != top) continue;
    ++count;
    // Along (1, 1)/√2, both ends on the outline of [0, 2] × [0, 1].
    EXPECT_NEAR((l.b.x - l.a.x) - (l.b.y - l.a.y), 0, 1e-12);
    for (const Point3 p : {l.a, l.b}) {
      const bool on_outline = std::abs(p.x) < 1e-12 || std::abs(p.x - 2) < 1e-12 || std::abs(p.y) < 1e-12 ||
                              std::abs(p.y - 1) < 1e-12;
      EXPECT_TRUE(on_outline) << p.x << " " << p.y;
    }
    total += distance(l.a, l.b);
  }
  // Lines x − y = c at c = (k + ½)·(1/4)·... : the across direction is (−1, 1)/√2 (n × along), so the
  // values y − x = √2·c', c' = (k + ½)·√2/4, i.e. y − x = (k + ½)/2 for y − x in (−2, 1): k = −4 … 1.
  EXPECT_EQ(count, 6);
  // Each line y − x = v crosses the rectangle over x from max(0, −v) to min(2, 1 − v).
  double want = 0;
  for (int k = -4; k <= 1; ++k) {
    const double v = (k + 0.5) / 2;
    want += std::sqrt(2.0) * (std::min(2.0, 1 - v) - std::max(0.0, -v));
  }
  EXPECT_NEAR(total, want, 1e-12);
}

TEST(Hatching, HolesCutTheLines) {
  // A 4 × 4 square with a 2 × 2 hole in the middle, extruded: on the top face, lines through the hole are
  // two pieces, the others one.
  const std::vector<Point2> outer = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const std::vector<Point2> hole = {{1, 1}, {1, 3}, {3, 3}, {3, 1}};
  const Solid p = gen::prism(outer, {hole}, 0, 1);
  HatchSpec spec;
  spec.spacing = 1;
  spec.angle_deg = 0;
  const FaceIndex top = face_facing(p, {0, 0, 1});
  std::map<double, std::vector<std::pair<double, double>>> by_y;
  for (const HatchLine& l : hatch_lines(hatched(p, spec)))
    if (l.face == top) by_y[l.a.y].push_back(std::minmax(l.a.x, l.b.x));
  ASSERT_EQ(by_y.size(), 4u);  // y = 0.5, 1.5, 2.5, 3.5
  for (auto& [y, pieces] : by_y) {
    std::sort(pieces.begin(), pieces.end());
    if (y > 1 && y < 3) {
      ASSERT_EQ(pieces.size(), 2u) << y;
      EXPECT_DOUBLE_EQ(pieces[0].first, 0);
      EXPECT_DOUBLE_EQ(pieces[0].second, 1);
      EXPECT_DOUBLE_EQ(pieces[1].first, 3);
      EXPECT_DOUBLE_EQ(pieces[1].second, 4);
    } else {
      ASSERT_EQ(pieces.size(), 1u) << y;
      EXPECT_DOUBLE_EQ(pieces[0].first, 0);
      EXPECT_DOUBLE_EQ(pieces[0].second, 4);
    }
  }
}

TEST(Hatching, LightGivesFourTones) {
  // A box lit along (0, −1, 2)/√5: top n·l = 0.894 (darkness 0.11: bare), the wall facing −y 0.447
  // (darkness 0.55: every second line), the walls facing ±x 0 (darkness 1: every line and a crossing set
  // every second line), the wall facing +y and the bottom below 0 (darkness 1 too).
  const Solid box = gen::box({0, 0, 0}, {1, 1, 1});
  HatchSpec spec;
  spec.spacing = 0.125;
  spec.angle_deg = 0;
  spec.light = Vector3{0, -1, 2};
  std::map<FaceIndex, int> per_face;
  for (const HatchLine& l : hatch_lines(hatched(box, spec))) ++per_face[l.face];
  EXPECT_EQ(per_face.count(face_facing(box, {0, 0, 1})), 0u);
  EXPECT_EQ(per_face[face_facing(box, {0, -1, 0})], 4);  // (2k + ½)/8 in [0, 1]: k = 0 … 3
  for (const Vector3 n : {Vector3{1, 0, 0}, Vector3{-1, 0, 0}, Vector3{0, 1, 0}, Vector3{0, 0, -1}})
    EXPECT_EQ(per_face[face_facing(box, n)], 8 + 4) << n.x << n.y << n.z;
  // A face between: lit at 0.6 (darkness 0.4) gets every fourth line.
  spec.light = Vector3{0, -0.6, 0.8};
  for (const HatchLine& l : hatch_lines(hatched(box, spec))) ++per_face[l.face + 100];
  EXPECT_EQ(per_face[face_facing(box, {0, -1, 0}) + 100], 2);  // (4k + ½)/8: k = 0, 1
}

TEST(Hatching, CrossAddsASetAtRightAngles) {
  const Solid box = gen::box({0, 0, 0}, {1, 1, 1});
  HatchSpec spec;
  spec.spacing = 0.25;
  spec.angle_deg = 30;
  spec.cross = true;
  const FaceIndex top = face_facing(box, {0, 0, 1});
  std::vector<Vector3> directions;
  for (const HatchLine& l : hatch_lines(hatched(box, spec)))
    if (l.face == top) directions.push_back(normalize(l.b - l.a));
  // Two directions, 30° and 120° from x (up to sign), at right angles.
  int first = 0, second = 0;
  for (const Vector3 d : directions) {
    const double a = std::atan2(d.y, d.x) * 180 / 3.14159265358979323846;
    const double m = std::fmod(a + 360, 180);
    if (std::abs(m - 30) < 1e-9) ++first;
    if (std::abs(m - 120) < 1e-9) ++second;
  }
  EXPECT_EQ(first + second, static_cast<int>(directions.size()));
  EXPECT_GT(first, 0);
  EXPECT_GT(second, 0);
}

TEST(Hatching, CoplanarTrianglesShareTheirLinesEnds) {
  // The box as triangles: each line across a face's diagonal is two pieces meeting at one point, the same
  // bits from both triangles (found from the diagonal's lower vertex on both sides).
  const Solid box = gen::box({0, 0, 0}, {1, 1, 1});
  const Solid tri = mesh_solid(box.vertices, triangles_of(box));
  HatchSpec spec;
  spec.spacing = 0.1;
  spec.angle_deg = 20;
  const auto lines = hatch_lines(hatched(tri, spec));
  const auto ends = line_ends(lines);
  // Every end inside a face (off the box's edges) is shared by exactly two pieces.
  int inner = 0;
  for (const auto& [p, n] : ends) {
    const auto [x, y, z] = p;
    int on_sides = 0;
    for (const double c : {x, y, z}) on_sides += (c == 0 || c == 1);
    if (on_sides >= 2) continue;  // on an edge of the box
    ++inner;
    EXPECT_EQ(n, 2) << x << " " << y << " " << z;
  }
  EXPECT_GT(inner, 30);
}

TEST(Hatching, PlanesCutABoxIntoRings) {
  // Planes z = 0.125 … 0.875 cut the four walls of a unit box into four closed rings; the top and bottom,
  // parallel to the planes, get none. Each ring's corners are found once, from the box's upright edges, so
  // every end is shared by the two walls' lines exactly.
  const Solid box = gen::box({0, 0, 0}, {1, 1, 1});
  HatchSpec spec;
  spec.spacing = 0.25;
  spec.planes = Vector3{0, 0, 3};
  const auto lines = hatch_lines(hatched(box, spec));
  ASSERT_EQ(lines.size(), 16u);
  std::set<double> zs;
  for (const HatchLine& l : lines) {
    EXPECT_EQ(l.a.z, l.b.z);
    EXPECT_NEAR(distance(l.a, l.b), 1, 1e-15);
    zs.insert(l.a.z);
  }
  EXPECT_EQ(zs, (std::set<double>{0.125, 0.375, 0.625, 0.875}));
  const auto ends = line_ends(lines);
  EXPECT_EQ(ends.size(), 16u);
  for (const auto& [p, n] : ends) EXPECT_EQ(n, 2);
}

TEST(Hatching, PlanesRunUnbrokenAcrossACurvedMesh) {
  // A sphere of 16 × 8 faces cut by tilted planes: each cut is a closed polygon across many faces, so every
  // end of every line is the end of exactly one other, to the bit.
  const Solid sphere = gen::sphere({0.3, -0.2, 0.1}, 1, 16, 8, 30);
  HatchSpec spec;
  spec.spacing = 0.1;
  spec.planes = Vector3{0.2, 0.1, 1};
  const auto lines = hatch_lines(hatched(sphere, spec));
  EXPECT_GT(lines.size(), 200u);
  for (const auto& [p, n] : line_ends(lines)) {
    const auto [x, y, z] = p;
    EXPECT_EQ(n, 2) << x << " " << y << " " << z;
  }
  // Each lies in its plane: 0.2x + 0.1y + z, over the normal's length, is (k + ½)·0.1.
  const double len = std::sqrt(0.2 * 0.2 + 0.1 * 0.1 + 1);
  for (const HatchLine& l : lines)
    for (const Point3 p : {l.a, l.b}) {
      const double c = (0.2 * p.x + 0.1 * p.y + p.z) / len / 0.1 - 0.5;
      EXPECT_NEAR(c, std::round(c), 1e-9);
    }
}

TEST(Hatching, BoundCountsEveryLine) {
  const Solid sphere = gen::sphere({0, 0, 0}, 1, 16, 8, 30);
  HatchSpec spec;
  spec.spacing = 0.05;
  spec.light = Vector3{1, 1, 1};
  std::size_t lines = 0;
  for (const SolidEdge& e : hatched(sphere, spec).edges) lines += e.kind == EdgeKind::Hatch;
  EXPECT_GT(lines, 100u);
  EXPECT_GE(hatch_line_bound(sphere, spec), lines);
}

TEST(Hatching, BadSpecsAreRefused) {
  const Solid box = gen::box({0, 0, 0}, {1, 1, 1});
  HatchSpec spec;
  spec.spacing = 0;
  EXPECT_THROW(hatched(box, spec), std::invalid_argument);
  spec.spacing = 1;
  spec.light = Vector3{0, 0, 0};
  EXPECT_THROW(hatched(box, spec), std::invalid_argument);
  spec.light.reset();
  spec.planes = Vector3{0, 0, 0};
  EXPECT_THROW(hatched(box, spec), std::invalid_argument);
}

TEST(Hatching, MovesWithTheSolidAndKeepsItsPen) {
  const Solid box = gen::box({0, 0, 0}, {1, 1, 1});
  HatchSpec spec;
  spec.spacing = 0.25;
  Solid h = hatched(box, spec);
  h.hatch_pen = 4;
  const Solid moved = h.transformed(Affine3::translation({5, 0, 0}));
  EXPECT_EQ(moved.hatch_pen, 4);
  EXPECT_EQ(hatch_lines(moved).size(), hatch_lines(h).size());
  solid_test::expect_valid_solid(moved);
}

}  // namespace
}  // namespace hlr::test
