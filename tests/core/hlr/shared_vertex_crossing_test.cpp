// Faces that pass through each other from a vertex they share (tracker issue 42): a fold through a fan,
// two sheets welded at one point. The crossing line starts at the shared vertex; where it ends is worked
// out here from how the triangles were made, and the drawing is checked against the ray-casting oracle,
// whose search for crossings within one solid covers every pair of faces sharing at most one vertex.
//   hlr_core_tests --gtest_filter='SharedVertexCrossing*'
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "core/solid/solid_builder.hpp"
#include "tests/support/ray_caster_checks.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::test {
namespace {

// Two triangles V, A1, A2 and V, B1, B2 made around a ray V + λ·d: each has one corner on each side of
// the ray, in planes through it at `angle` radians to each other. With `across` the second is made
// around −d instead, and they meet only at V.
struct CornerPair {
  Point3 v, a1, a2, b1, b2;
  Vector3 d;
  double length = 0;  // of the crossing, V to where the nearer triangle ends along d; 0 when across
};

CornerPair corner_pair(Rng& r, double angle, bool across) {
  CornerPair p;
  p.v = r.point({-1, -1, -1}, {1, 1, 1});
  p.d = r.direction();
  // Two unit vectors across d, `angle` apart about it: the planes' in-plane directions off the ray.
  Vector3 e = normalize(cross(p.d, r.direction()));
  const Vector3 f = cross(p.d, e);
  const Vector3 ea = e, eb = std::cos(angle) * e + std::sin(angle) * f;
  // A triangle's corners at s along the ray and w off it (one on each side); its far edge meets the ray
  // at s1 + (s2 − s1)·w1/(w1 + w2).
  auto corners = [&](Vector3 along, Vector3 off, Point3& c1, Point3& c2) {
    const double s1 = r(0.3, 1.2), s2 = r(0.3, 1.2), w1 = r(0.2, 1), w2 = r(0.2, 1);
    c1 = p.v + s1 * along + w1 * off;
    c2 = p.v + s2 * along - w2 * off;
    return s1 + (s2 - s1) * w1 / (w1 + w2);
  };
  const double la = corners(p.d, ea, p.a1, p.a2);
  const double lb = corners(across ? -p.d : p.d, eb, p.b1, p.b2);
  p.length = across ? 0 : std::min(la, lb);
  return p;
}

Solid pair_solid(const CornerPair& p) {
  SolidBuilder builder;
  const VertexIndex v = builder.add_vertex(p.v), a1 = builder.add_vertex(p.a1), a2 = builder.add_vertex(p.a2),
                    b1 = builder.add_vertex(p.b1), b2 = builder.add_vertex(p.b2);
  const std::vector<VertexIndex> fa{v, a1, a2}, fb{v, b1, b2};
  builder.add_indexed_face_loop(fa);
  builder.add_indexed_face_loop(fb);
  SolidBuildResult built = builder.build();
  EXPECT_TRUE(built.ok());
  return built.ok() ? std::move(*built.solid) : Solid{};
}

// The crossing is found from the shared vertex to where the first triangle ends, at every angle between
// the planes from a right angle down to a tenth of a degree; made across, nothing is found.
TEST(SharedVertexCrossing, FoundFromTheVertexOn) {
  Rng r(42);
  int crossing = 0;
  for (int n = 0; n < 400; ++n) {
    const double angle = std::numbers::pi / 180 * (n % 4 == 0 ? r(0.1, 1) : r(1, 90));
    const bool across = n % 5 == 4;
    const CornerPair p = corner_pair(r, angle, across);
    const Solid solid = pair_solid(p);
    ASSERT_EQ(solid.faces.size(), 2u);
    const auto& found = solid.self_crossings();
    if (across) {
      EXPECT_TRUE(found.empty()) << "case " << n << ": triangles on opposite sides of their vertex cross";
      continue;
    }
    ASSERT_EQ(found.size(), 1u) << "case " << n << ", planes " << angle * 180 / std::numbers::pi << "° apart";
    const SelfCrossing& x = found[0];
    EXPECT_TRUE(x.p0 == p.v) << "case " << n << ": the line starts at the shared vertex";
    const Point3 end = p.v + p.length * p.d;
    EXPECT_LT(distance(x.p1, end), 1e-9) << "case " << n;
    ++crossing;
  }
  EXPECT_EQ(crossing, 320);
}

// Parallelograms V, A1, A1 + A2 − V, A2 made on the same corners: faces of four, which the grid meets
// (not the fans of triangles). They cross from V until the nearer one ends along d — where
// d = α·(A1 − V) + β·(A2 − V) reaches the far sides, at λ = 1 / max(α, β) — and made across, not at all.
TEST(SharedVertexCrossing, QuadsRoundOneVertex) {
  Rng r(4343);
  int crossing = 0;
  for (int n = 0; n < 200; ++n) {
    const bool across = n % 5 == 4;
    const CornerPair p = corner_pair(r, std::numbers::pi / 180 * r(1, 90), across);
    auto reach = [&](Point3 c1, Point3 c2, Vector3 d) {  // λ where V + λ·d leaves the parallelogram
      const Vector3 u = c1 - p.v, w = c2 - p.v;
      const double uu = dot(u, u), uw = dot(u, w), ww = dot(w, w), ud = dot(u, d), wd = dot(w, d);
      const double det = uu * ww - uw * uw;
      const double alpha = (ud * ww - wd * uw) / det, beta = (wd * uu - ud * uw) / det;
      return 1 / std::max(alpha, beta);
    };
    SolidBuilder builder;
    const VertexIndex v = builder.add_vertex(p.v), a1 = builder.add_vertex(p.a1),
                      a2 = builder.add_vertex(p.a2), b1 = builder.add_vertex(p.b1),
                      b2 = builder.add_vertex(p.b2);
    const VertexIndex a3 = builder.add_vertex(p.a1 + (p.a2 - p.v)),
                      b3 = builder.add_vertex(p.b1 + (p.b2 - p.v));
    builder.add_indexed_face_loop(std::vector<VertexIndex>{v, a1, a3, a2});
    builder.add_indexed_face_loop(std::vector<VertexIndex>{v, b1, b3, b2});
    SolidBuildResult built = builder.build();
    ASSERT_TRUE(built.ok()) << "case " << n;
    const auto& found = built.solid->self_crossings();
    if (across) {
      EXPECT_TRUE(found.empty()) << "case " << n
                                 << ": parallelograms on opposite sides of their vertex cross";
      continue;
    }
    ASSERT_FALSE(found.empty()) << "case " << n;
    double length = 0;
    for (const SelfCrossing& x : found) length += distance(x.p0, x.p1);
    const double expected = std::min(reach(p.a1, p.a2, p.d), reach(p.b1, p.b2, p.d));
    EXPECT_NEAR(length, expected, 1e-9) << "case " << n;
    ++crossing;
  }
  EXPECT_EQ(crossing, 160);
}

// Seen from 120 random views, each pair's crossing is drawn wherever the oracle sees it, and nothing drawn
// is hidden: the missing share of the required line, 0.52 % in every view before, is none.
TEST(SharedVertexCrossing, DrawnInEveryViewAsTheOracleSees) {
  Rng r(4242);
  int views = 0, expected = 0;
  for (int n = 0; n < 120; ++n) {
    const CornerPair p = corner_pair(r, std::numbers::pi / 180 * r(0.5, 90), false);
    Scene scene;
    scene.objects.push_back({"pair", std::make_shared<const Solid>(pair_solid(p))});
    const Point3 target = p.v + 0.4 * p.d;
    const Point3 eye = target + r(3, 5) * r.direction();
    const bool ortho = n % 3 == 2;
    const Camera camera = ortho ? ortho_camera(OrthoParameters{eye, target, {0, 0, 1}, 3, 0})
                                : lookat_camera(LookatParameters{eye, target, {0, 0, 1}, r(30, 60), 0, 0});
    const FrameResult result = render_frame(scene, camera);
    const CheckReport report = check_frame(scene, camera, result);
    std::ostringstream where;
    where << "view " << n << (ortho ? " ortho" : " lookat") << " eye (" << eye.x << ", " << eye.y << ", "
          << eye.z << ")";
    EXPECT_TRUE(report.ok()) << where.str() << "\n" << report.summary();
    expected += report.intersection_expected > 0;
    ++views;
  }
  EXPECT_EQ(views, 120);
  EXPECT_GE(expected, 100) << "the oracle expected crossing lines in too few views for the test to mean much";
}

}  // namespace
}  // namespace hlr::test
