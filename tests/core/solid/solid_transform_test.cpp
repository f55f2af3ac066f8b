// Solid::transformed and newell_normal.
#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>

#include "tests/core/solid/solid_test_helpers.hpp"

namespace hlr {
namespace {

using namespace solid_test;

TEST(SolidNewell, SquareAndTriangle) {
  const std::vector<Point3> v = {{0, 0, 5}, {2, 0, 5}, {2, 2, 5}, {0, 2, 5}};
  const Vector3 n = newell_normal(v, Ring{{0, 1, 2, 3}, {}});
  EXPECT_EQ(n, Vector3(0, 0, 8));  // twice the area of the 2×2 square, right-handed
  EXPECT_EQ(newell_normal(v, Ring{{3, 2, 1, 0}, {}}), Vector3(0, 0, -8));
  EXPECT_EQ(newell_normal(v, Ring{{0, 1}, {}}), Vector3());
  // Far from the origin the result is still exact for exactly representable data.
  const std::vector<Point3> far = {{1e9, 1e9, 1e9}, {1e9 + 1, 1e9, 1e9}, {1e9, 1e9 + 1, 1e9}};
  EXPECT_EQ(newell_normal(far, Ring{{0, 1, 2}, {}}), Vector3(0, 0, 1));
}

Solid cube() {
  const SolidBuildResult r = unit_cube().build();
  EXPECT_TRUE(r.ok());
  return *r.solid;
}

// Outward: every face's normal points away from the solid's vertex mean (convex solids only).
void expect_outward_convex(const Solid& s) {
  Vector3 mean{};
  for (const Point3& p : s.vertices) mean += to_vector(p) / static_cast<double>(s.vertices.size());
  for (std::size_t f = 0; f < s.faces.size(); ++f)
    EXPECT_LT(s.planes[f].signed_distance(to_point(mean)), 0) << "face " << f;
}

TEST(SolidTransform, RigidMotionKeepsEverything) {
  const Solid s = cube();
  const Affine3 m = Affine3::rotation({1, 2, 3}, 0.7).then(Affine3::translation({10, -4, 2}));
  const Solid t = s.transformed(m);
  expect_valid_solid(t);
  expect_outward_convex(t);
  EXPECT_NEAR(signed_volume(t), 1, 1e-12);
  ASSERT_EQ(t.edges.size(), s.edges.size());
  for (std::size_t i = 0; i < s.edges.size(); ++i) {
    EXPECT_EQ(t.edges[i].v0, s.edges[i].v0);
    EXPECT_EQ(t.edges[i].left, s.edges[i].left);
    EXPECT_EQ(t.edges[i].kind, s.edges[i].kind);
  }
  EXPECT_EQ(t.closed, s.closed);
  const Point3 p = m.apply(s.vertices[6]);
  EXPECT_EQ(t.vertices[6], p);
}

TEST(SolidTransform, MirrorKeepsFacesOutward) {
  for (const Affine3& m : {Affine3::scaling(-1, 1, 1), Affine3::scaling(2, -3, 0.5),
                           Affine3::scaling(-1, -1, -1).then(Affine3::translation({5, 5, 5}))}) {
    const Solid t = cube().transformed(m);
    expect_valid_solid(t);  // left still runs v0→v1, right v1→v0, rings counter-clockwise
    expect_outward_convex(t);
    EXPECT_GT(signed_volume(t), 0);
    EXPECT_NEAR(std::abs(signed_volume(t)), std::abs(m.determinant()), 1e-12);
  }
}

TEST(SolidTransform, MirrorOfAnOpenSurfaceKeepsTheFaceLeftOfItsBoundary) {
  SolidBuilder b;
  b.add_vertex("a", {0, 0, 0});
  b.add_vertex("b", {1, 0, 0});
  b.add_vertex("c", {0, 1, 0});
  b.add_face({"a", "b", "c"});
  const SolidBuildResult r = b.build();
  ASSERT_TRUE(r.ok());
  const Solid t = r.solid->transformed(Affine3::scaling(1, 1, -1));
  expect_valid_solid(t);
  EXPECT_NEAR(t.planes[0].normal.z, -1, 1e-15);  // a z-mirror turns the face over
  for (const SolidEdge& e : t.edges) {
    EXPECT_EQ(e.kind, EdgeKind::Boundary);
    EXPECT_EQ(e.left, 0);
  }
}

TEST(SolidTransform, SingularMapThrows) {
  EXPECT_THROW(cube().transformed(Affine3::scaling(1, 0, 1)), std::domain_error);
  EXPECT_THROW(cube().transformed(Affine3::scaling(1, std::numeric_limits<double>::infinity(), 1)),
               std::domain_error);
}

TEST(SolidTransform, StretchReclassifiesSmoothAgainstFeature) {
  // A 16-sided prism at crease 30°: every side edge Smooth (22.5°). Stretched 10× in x, the side faces
  // near ±y turn sharply and those edges become Feature; Flat and concave flags are unaffected.
  SolidBuildOptions o;
  o.crease_angle_deg = 30;
  SolidBuilder b(o);
  std::vector<std::string> bottom, top;
  const int n = 16;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    b.add_vertex(id("b", i), {std::cos(a), std::sin(a), 0});
    b.add_vertex(id("t", i), {std::cos(a), std::sin(a), 1});
    bottom.insert(bottom.begin(), id("b", i));
    top.push_back(id("t", i));
  }
  b.add_face(bottom);
  b.add_face(top);
  for (int i = 0; i < n; ++i) {
    const std::string p = std::to_string(i), q = std::to_string((i + 1) % n);
    b.add_face({"b" + p, "b" + q, "t" + q, "t" + p});
  }
  const SolidBuildResult r = b.build();
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(count_kind(*r.solid, EdgeKind::Smooth), static_cast<std::size_t>(n));
  const Solid t = r.solid->transformed(Affine3::scaling(10, 1, 1));
  const std::size_t smooth = count_kind(t, EdgeKind::Smooth);
  EXPECT_GT(smooth, 0u);
  EXPECT_LT(smooth, static_cast<std::size_t>(n));
  EXPECT_EQ(count_kind(t, EdgeKind::Smooth) + count_kind(t, EdgeKind::Feature), 3u * n);
  EXPECT_EQ(t.crease_angle_deg, 30);
}

}  // namespace
}  // namespace hlr
