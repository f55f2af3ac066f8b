// Albers (1988): the tetrahedron views of 000_albers.md §4.1 (centred reconstruction of TETRA.VER with
// the exact TETRA.SUR loops) and the erasure-merge worked example of §4.4 (Tables VI–IX).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include "core/camera/orbit_camera.hpp"
#include "core/hlr/interval_set.hpp"
#include "core/hlr/render_frame.hpp"
#include "core/solid/solid_builder.hpp"

namespace hlr {
namespace {

Solid tetrahedron() {
  SolidBuilder b;
  b.add_vertex("1", {5.773502692, 10, 0});
  b.add_vertex("2", {5.773502692, -10, 0});
  b.add_vertex("3", {-11.547005384, 0, 0});
  b.add_vertex("4", {0, 0, 16.329931620});
  // TETRA.SUR: 03 01 04 02 01 / 03 01 03 04 01 / 03 03 02 04 03 / 03 01 02 03 01
  b.add_face({"1", "4", "2"});
  b.add_face({"1", "3", "4"});
  b.add_face({"3", "2", "4"});
  b.add_face({"1", "2", "3"});
  SolidBuildResult r = b.build();
  EXPECT_TRUE(r.ok());
  for (const auto& d : r.diagnostics) ADD_FAILURE() << d.message;
  return *r.solid;
}

using EdgeSet = std::set<std::pair<int, int>>;

EdgeSet visible_edges(const Solid& solid, const Camera& camera) {
  Scene scene;
  scene.objects.push_back({"tetra", solid});
  const FrameResult result = render_frame(scene, camera);
  EdgeSet edges;
  for (const VisibleSegment& s : result.segments) {
    const SolidEdge& e = solid.edges[s.edge];
    // A convex solid shows each visible edge whole: no partial erasures (§4.1).
    EXPECT_NEAR(distance(s.p0, s.p1), distance(solid.vertices[e.v0], solid.vertices[e.v1]), 1e-9);
    const int a = static_cast<int>(e.v0) + 1, b = static_cast<int>(e.v1) + 1;
    edges.insert({std::min(a, b), std::max(a, b)});
  }
  return edges;
}

Camera albers_view(double theta, double phi) {
  OrbitParameters p;
  p.theta_deg = theta * 180 / std::numbers::pi;
  p.phi_deg = phi * 180 / std::numbers::pi;
  p.rho = 425;
  p.d = 1549;
  return orbit_camera(p);
}

TEST(AlbersTetrahedron, View1OnlyTheFrontFaceS1) {
  // θ = 0, φ = π/2: the base S4 is exactly edge-on and counts as a back face.
  EXPECT_EQ(visible_edges(tetrahedron(), albers_view(0, std::numbers::pi / 2)), (EdgeSet{{1, 2}, {1, 4}, {2, 4}}));
}

TEST(AlbersTetrahedron, View2FrontFacesS1AndS2) {
  EXPECT_EQ(visible_edges(tetrahedron(), albers_view(std::numbers::pi / 4, std::numbers::pi / 2)),
            (EdgeSet{{1, 2}, {1, 4}, {2, 4}, {1, 3}, {3, 4}}));
}

TEST(AlbersTetrahedron, View3HidesEdge2To3AndMatchesTheScreenValues) {
  const Camera camera = albers_view(std::numbers::pi / 4, std::numbers::pi / 3);
  const Solid solid = tetrahedron();
  EXPECT_EQ(visible_edges(solid, camera), (EdgeSet{{1, 2}, {1, 4}, {2, 4}, {1, 3}, {3, 4}}));
  // Screen = (155 + D·Xe/Ze, 89 − 0.93·D·Ye/Ze) on Albers' CGA device (§2.3, §4.1).
  const double screen[4][2] = {{166.146, 108.343}, {114.595, 83.966}, {184.272, 75.389}, {155.000, 40.125}};
  for (int i = 0; i < 4; ++i) {
    const Point2 p = camera.project(solid.vertices[i]);
    EXPECT_NEAR(155 + p.x, screen[i][0], 1e-3) << "v" << i + 1;
    EXPECT_NEAR(89 - 0.93 * p.y, screen[i][1], 1e-3) << "v" << i + 1;
  }
}

// §4.4: edge (v3, v4) projected (122,130) → (200,200); erasures (.20,.40), (.80,.85), then (.30,.50), which
// overlaps the first (type 1), giving Table IX: (.20,.50), (.80,.85). The edge is drawn on the gaps.
TEST(AlbersErasure, WorkedExampleTablesVIToIX) {
  IntervalSet erasures;
  erasures.add(0.20, 0.40);
  EXPECT_EQ(erasures.normalize().size(), 1u);  // Table VII
  erasures.add(0.80, 0.85);
  EXPECT_EQ(erasures.normalize().size(), 2u);  // Table VIII
  erasures.add(0.30, 0.50);
  const auto& table9 = erasures.normalize();
  ASSERT_EQ(table9.size(), 2u);
  EXPECT_DOUBLE_EQ(table9[0].lo, 0.20);
  EXPECT_DOUBLE_EQ(table9[0].hi, 0.50);
  EXPECT_DOUBLE_EQ(table9[1].lo, 0.80);
  EXPECT_DOUBLE_EQ(table9[1].hi, 0.85);
  const auto visible = erasures.complement();
  ASSERT_EQ(visible.size(), 3u);
  const Point2 a{122, 130}, b{200, 200};
  // Visible output [D] of §4.4: (122,130)–(137.6,144), (161,165)–(184.4,186), (188.3,189.5)–(200,200).
  const double expect[3][4] = {{122, 130, 137.6, 144}, {161, 165, 184.4, 186}, {188.3, 189.5, 200, 200}};
  for (int i = 0; i < 3; ++i) {
    const Point2 p = lerp(a, b, visible[i].lo), q = lerp(a, b, visible[i].hi);
    EXPECT_NEAR(p.x, expect[i][0], 0.05);
    EXPECT_NEAR(p.y, expect[i][1], 0.05);
    EXPECT_NEAR(q.x, expect[i][2], 0.05);
    EXPECT_NEAR(q.y, expect[i][3], 0.05);
  }
}

}  // namespace
}  // namespace hlr
