// Every generator builds a valid solid: counts, topology (Euler–Poincaré with holes: V − E + F − H =
// 2(1 − genus), counting only edges on faces), closedness, outward orientation (positive volume), the
// expected edge kinds, and determinism of the seeded generators.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "stdlib/generators.hpp"

namespace hlr::stdlib {
namespace {

struct Counts {
  long v = 0, e = 0, f = 0, holes = 0;
  long euler() const { return v - e + f - holes; }
};

// Edges on faces only (markings and free lines are not part of the surface's cell complex).
Counts counts(const Solid& s) {
  Counts c;
  c.v = static_cast<long>(s.vertices.size());
  c.f = static_cast<long>(s.faces.size());
  for (const auto& e : s.edges)
    if (e.kind != EdgeKind::Marking && e.kind != EdgeKind::Free) ++c.e;
  for (const auto& f : s.faces) c.holes += static_cast<long>(f.rings.size()) - 1;
  return c;
}

long count_kind(const Solid& s, EdgeKind k) {
  return std::count_if(s.edges.begin(), s.edges.end(), [k](const SolidEdge& e) { return e.kind == k; });
}

// Divergence theorem over the rings' Newell normals: positive exactly when the faces point outward.
double volume(const Solid& s) {
  double v = 0;
  for (const auto& f : s.faces)
    for (const auto& r : f.rings) v += dot(to_vector(s.vertices[r.vertices[0]]), newell_normal(s.vertices, r));
  return v / 6;
}

// Every stored plane agrees with the face's own Newell normal and passes through its vertices.
void expect_planes_consistent(const Solid& s) {
  ASSERT_EQ(s.planes.size(), s.faces.size());
  for (std::size_t i = 0; i < s.faces.size(); ++i) {
    const Vector3 n = newell_normal(s.vertices, s.faces[i].rings[0]);
    EXPECT_GT(dot(n, s.planes[i].normal), 0) << "face " << i;
    for (const auto& r : s.faces[i].rings)
      for (VertexIndex v : r.vertices) EXPECT_NEAR(s.planes[i].signed_distance(s.vertices[v]), 0, 1e-9) << "face " << i;
  }
}

TEST(Generators, Box) {
  const Solid s = box({-1, 0, 2}, {3, 2, 5});
  const Counts c = counts(s);
  EXPECT_EQ(c.v, 8);
  EXPECT_EQ(c.e, 12);
  EXPECT_EQ(c.f, 6);
  EXPECT_EQ(c.euler(), 2);
  EXPECT_TRUE(s.closed);
  EXPECT_EQ(count_kind(s, EdgeKind::Feature), 12);
  EXPECT_NEAR(volume(s), 4 * 2 * 3, 1e-12);
  expect_planes_consistent(s);
  EXPECT_THROW(box({0, 0, 0}, {1, 0, 1}), std::invalid_argument);
}

TEST(Generators, RotatedBox) {
  const Solid s = rotated_box({1, 2, 3}, {2, 4, 6}, {1, 1, 0}, 33);
  EXPECT_EQ(counts(s).euler(), 2);
  EXPECT_TRUE(s.closed);
  EXPECT_NEAR(volume(s), 48, 1e-9);
  for (const Point3& p : s.vertices) EXPECT_NEAR(distance(p, {1, 2, 3}), std::sqrt(1 + 4 + 9.0), 1e-12);
  expect_planes_consistent(s);
}

TEST(Generators, LBlockIsConcaveWithOneConcaveEdge) {
  const Solid s = l_block({0, 0, 0}, {2, 1, 2}, 1, 1);  // Pfister's L prism (outline in x–z)
  const Counts c = counts(s);
  EXPECT_EQ(c.v, 12);
  EXPECT_EQ(c.e, 18);
  EXPECT_EQ(c.f, 8);
  EXPECT_EQ(c.euler(), 2);
  EXPECT_TRUE(s.closed);
  EXPECT_NEAR(volume(s), 3, 1e-12);
  EXPECT_EQ(std::count_if(s.edges.begin(), s.edges.end(), [](const SolidEdge& e) { return e.concave; }), 1);
  for (const Point3& p : s.vertices) {
    EXPECT_TRUE(p.x >= 0 && p.x <= 2 && p.y >= 0 && p.y <= 1 && p.z >= 0 && p.z <= 2);
    EXPECT_FALSE(p.x > 1 && p.z > 1);  // the notch is empty
  }
  expect_planes_consistent(s);
}

TEST(Generators, Stairs) {
  for (int n : {1, 3, 7}) {
    SCOPED_TRACE(n);
    const Solid s = stairs(n, 2, 0.2, 0.3);
    const Counts c = counts(s);
    EXPECT_EQ(c.f, 2 * n + 4);
    EXPECT_EQ(c.v, 2 * (2 * n + 2));
    EXPECT_EQ(c.euler(), 2);
    EXPECT_TRUE(s.closed);
    // Volume: step i is a column of height (i + 1)·rise.
    EXPECT_NEAR(volume(s), 2 * 0.3 * 0.2 * n * (n + 1) / 2.0, 1e-12);
    EXPECT_EQ(std::count_if(s.edges.begin(), s.edges.end(), [](const SolidEdge& e) { return e.concave; }), n - 1);
    expect_planes_consistent(s);
  }
}

TEST(Generators, PrismWithHoleHasGenusOne) {
  const Solid s = prism({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {3, 1}, {3, 3}, {1, 3}}}, 0, 1);
  const Counts c = counts(s);
  EXPECT_EQ(c.v, 16);
  EXPECT_EQ(c.f, 10);
  EXPECT_EQ(c.holes, 2);
  EXPECT_EQ(c.euler(), 0);
  EXPECT_TRUE(s.closed);
  EXPECT_NEAR(volume(s), 12, 1e-12);
  // A clockwise outline and a counter-clockwise hole are reoriented, not rejected.
  const Solid t = prism({{0, 4}, {4, 4}, {4, 0}, {0, 0}}, {{{1, 1}, {1, 3}, {3, 3}, {3, 1}}}, 0, 1);
  EXPECT_NEAR(volume(t), 12, 1e-12);
  expect_planes_consistent(s);
}

TEST(Generators, PlateWithHoles) {
  const Solid s = plate_with_holes({0, 0, 0}, {6, 4, 0.5}, 3, 2, 0.5, 6);
  const Counts c = counts(s);
  EXPECT_EQ(c.f, 2 + 4 + 6 * 6);
  EXPECT_EQ(c.holes, 2 * 6);
  EXPECT_EQ(c.euler(), 2 * (1 - 6));
  EXPECT_TRUE(s.closed);
  EXPECT_GT(volume(s), 0);
  EXPECT_LT(volume(s), 6 * 4 * 0.5);
  expect_planes_consistent(s);
}

TEST(Generators, CylinderSmoothSides) {
  const Solid s = cylinder({0, 0, 0}, 1, 2, 8, 50);  // 45° between side faces < 50° crease
  EXPECT_EQ(counts(s).f, 10);
  EXPECT_EQ(count_kind(s, EdgeKind::Smooth), 8);
  EXPECT_EQ(count_kind(s, EdgeKind::Feature), 16);
  EXPECT_EQ(count_kind(cylinder({0, 0, 0}, 1, 2, 8, 0), EdgeKind::Feature), 24);
}

TEST(Generators, OpenBoxHasBoundaryRim) {
  const Solid s = open_box({0, 0, 0}, {1, 1, 1});
  EXPECT_FALSE(s.closed);
  EXPECT_EQ(counts(s).f, 5);
  EXPECT_EQ(count_kind(s, EdgeKind::Boundary), 4);
  EXPECT_EQ(count_kind(s, EdgeKind::Feature), 8);
}

TEST(Generators, MarkedBoxHasMarkingsAndFreeLine) {
  const Solid s = marked_box({0, 0, 0}, {2, 2, 1});
  EXPECT_TRUE(s.closed);
  EXPECT_EQ(counts(s).euler() - (static_cast<long>(s.vertices.size()) - 8), 2);  // 5 extra points on no face edge
  EXPECT_EQ(count_kind(s, EdgeKind::Marking), 2);
  EXPECT_EQ(count_kind(s, EdgeKind::Free), 1);
  EXPECT_EQ(count_kind(s, EdgeKind::Feature), 12);
}

TEST(Generators, Sphere) {
  const Solid s = sphere({1, 2, 3}, 2, 12, 8, 0);
  const Counts c = counts(s);
  EXPECT_EQ(c.f, 12 * 8);
  EXPECT_EQ(c.v, 12 * 7 + 2);
  EXPECT_EQ(c.euler(), 2);
  EXPECT_TRUE(s.closed);
  EXPECT_EQ(count_kind(s, EdgeKind::Feature), c.e);  // crease 0: no two faces are coplanar
  const double ball = 4.0 / 3 * std::numbers::pi * 8;
  EXPECT_GT(volume(s), 0.8 * ball);
  EXPECT_LT(volume(s), ball);
  const Solid smooth = sphere({0, 0, 0}, 1, 24, 12, 40);
  EXPECT_EQ(count_kind(smooth, EdgeKind::Smooth), counts(smooth).e);
  expect_planes_consistent(s);
}

TEST(Generators, TorusHasGenusOne) {
  const Solid s = torus({0, 0, 1}, 3, 1, 16, 8, 0);
  const Counts c = counts(s);
  EXPECT_EQ(c.f, 128);
  EXPECT_EQ(c.v, 128);
  EXPECT_EQ(c.e, 256);
  EXPECT_EQ(c.euler(), 0);
  EXPECT_TRUE(s.closed);
  const double exact = 2 * std::numbers::pi * std::numbers::pi * 3 * 1;
  EXPECT_GT(volume(s), 0.85 * exact);
  EXPECT_LT(volume(s), exact);
  expect_planes_consistent(s);
}

TEST(Generators, ClosedMesh100kTriangles) {
  const Solid s = closed_mesh(100000, 1);
  const Counts c = counts(s);
  EXPECT_NEAR(static_cast<double>(c.f), 100000, 1000);
  for (const auto& f : s.faces) ASSERT_EQ(f.rings[0].vertices.size(), 3u);
  EXPECT_EQ(c.euler(), 2);
  EXPECT_TRUE(s.closed);
  EXPECT_GT(volume(s), 0);
  // Nearly every edge is a Feature edge at crease 0.
  EXPECT_GT(static_cast<double>(count_kind(s, EdgeKind::Feature)), 0.99 * static_cast<double>(c.e));
}

TEST(Generators, ClosedMeshIsDeterministicAndSeeded) {
  const Solid a = closed_mesh(2000, 5), b = closed_mesh(2000, 5), d = closed_mesh(2000, 6);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  EXPECT_TRUE(std::equal(a.vertices.begin(), a.vertices.end(), b.vertices.begin()));
  EXPECT_FALSE(std::equal(a.vertices.begin(), a.vertices.end(), d.vertices.begin()));
  EXPECT_EQ(counts(a).euler(), 2);
  EXPECT_NEAR(static_cast<double>(a.faces.size()), 2000, 100);
  EXPECT_THROW(closed_mesh(0, 1), std::invalid_argument);
}

TEST(Generators, BoxCity) {
  const auto city = box_city(6, 5, 42);
  ASSERT_EQ(city.size(), 6u * 5 + 1);
  for (std::size_t i = 0; i < city.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_TRUE(city[i].closed);
    EXPECT_EQ(counts(city[i]).euler(), 2);
    EXPECT_GT(volume(city[i]), 0);
  }
  // Buildings stay inside their own cells (so they never interpenetrate) and stand on the ground.
  const CityOptions o;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j)
      for (const Point3& p : city[static_cast<std::size_t>(i * 5 + j)].vertices) {
        EXPECT_GE(p.x, i * o.cell + 0.5 * o.street - 1e-9);
        EXPECT_LE(p.x, (i + 1) * o.cell - 0.5 * o.street + 1e-9);
        EXPECT_GE(p.y, j * o.cell + 0.5 * o.street - 1e-9);
        EXPECT_LE(p.y, (j + 1) * o.cell - 0.5 * o.street + 1e-9);
        EXPECT_GE(p.z, 0);
        EXPECT_LE(p.z, o.max_height);
      }
  // Same seed, same city; the towers make some buildings L-shaped.
  const auto again = box_city(6, 5, 42);
  std::size_t towers = 0;
  for (std::size_t i = 0; i < city.size(); ++i) {
    EXPECT_TRUE(std::equal(city[i].vertices.begin(), city[i].vertices.end(), again[i].vertices.begin()));
    towers += city[i].faces.size() == 8;
  }
  EXPECT_GT(towers, 0u);
  CityOptions bare;
  bare.ground = false;
  EXPECT_EQ(box_city(3, 3, 1, bare).size(), 9u);
}

TEST(Generators, BadArgumentsThrow) {
  EXPECT_THROW(sphere({0, 0, 0}, 1, 2, 4, 0), std::invalid_argument);
  EXPECT_THROW(torus({0, 0, 0}, 1, 2, 8, 8, 0), std::invalid_argument);
  EXPECT_THROW(stairs(0, 1, 1, 1), std::invalid_argument);
  EXPECT_THROW(l_block({0, 0, 0}, {2, 1, 2}, 3, 1), std::invalid_argument);
  EXPECT_THROW(prism({{0, 0}, {1, 0}}, {}, 0, 1), std::invalid_argument);
  EXPECT_THROW(box_city(0, 3, 1), std::invalid_argument);
}

}  // namespace
}  // namespace hlr::stdlib
