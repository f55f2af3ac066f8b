// Occlusion levels (tracker issue 36): each hidden piece carries how many surfaces lie in front of it.
// Checked by hand on boxes in a row, and from random views against the ray-casting oracle counting the
// faces along each sight line.
//   hlr_core_tests --gtest_filter='OcclusionLevels*'
#include "core/hlr/occlusion_levels.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>

#include "core/camera/ortho_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "stdlib/generators.hpp"
#include "tests/support/mesh_views.hpp"
#include "tests/support/occlusion_level_checks.hpp"
#include "tests/support/ray_caster_checks.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::test {
namespace {

namespace gen = hlr::stdlib;

std::vector<LevelPiece> split(const std::vector<LevelCover>& covers, const std::vector<Interval>& runs,
                              double negligible = 0, int surplus = 0) {
  LevelScratch scratch;
  std::vector<LevelPiece> out;
  auto is_negligible = [&](double lo, double hi) { return hi - lo <= negligible; };
  split_by_level(covers, surplus, runs, is_negligible, scratch, out);
  return out;
}

void expect_pieces(const std::vector<LevelPiece>& got, const std::vector<LevelPiece>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_DOUBLE_EQ(got[i].lo, want[i].lo) << i;
    EXPECT_DOUBLE_EQ(got[i].hi, want[i].hi) << i;
    EXPECT_EQ(got[i].level, want[i].level) << i;
  }
}

TEST(OcclusionLevels, CountsOverlappingCovers) {
  // Three covers: [0.1, 0.5], [0.3, 0.7], [0.4, 0.6] — one run [0.1, 0.7].
  expect_pieces(split({{0.1, 0.5}, {0.3, 0.7}, {0.4, 0.6}}, {{0.1, 0.7}}),
                {{0.1, 0.3, 1}, {0.3, 0.4, 2}, {0.4, 0.5, 3}, {0.5, 0.6, 2}, {0.6, 0.7, 1}});
}

TEST(OcclusionLevels, SliversAtSharedEdgesJoinTheirNeighbours) {
  // Two faces of one surface meeting at 0.5 up to rounding: overlapping (a level-2 sliver) and apart (a
  // gap the hidden run closed). Both are one piece of level 1.
  expect_pieces(split({{0.2, 0.5 + 1e-12}, {0.5 - 1e-12, 0.8}}, {{0.2, 0.8}}, 1e-9), {{0.2, 0.8, 1}});
  expect_pieces(split({{0.2, 0.5 - 1e-12}, {0.5 + 1e-12, 0.8}}, {{0.2, 0.8}}, 1e-9), {{0.2, 0.8, 1}});
  // A sliver at a run's start joins the piece after it; a real step stays.
  expect_pieces(split({{0.2, 0.8}, {0.2, 0.2 + 1e-12}, {0.6, 0.8}}, {{0.2, 0.8}}, 1e-9),
                {{0.2, 0.6, 1}, {0.6, 0.8, 2}});
}

TEST(OcclusionLevels, RunsAreSplitApart) {
  expect_pieces(split({{0.1, 0.2}, {0.5, 0.9}, {0.6, 0.7}}, {{0.1, 0.2}, {0.5, 0.9}}),
                {{0.1, 0.2, 1}, {0.5, 0.6, 1}, {0.6, 0.7, 2}, {0.7, 0.9, 1}});
}

TEST(OcclusionLevels, CulledSolidsCountTwoSurfacesAFrontFace) {
  // An edge on a culled solid's back, behind two of its front faces that overlap in the middle: each stands
  // for itself and the back face behind it, and the edge lies on one of those back faces.
  expect_pieces(split({{0, 0.6, 2}, {0.4, 1, 2}}, {{0, 1}}, 0, 1), {{0, 0.4, 1}, {0.4, 0.6, 3}, {0.6, 1, 1}});
}

// Looking along +y, orthographic: three unit boxes in a row at y 0, 2 and 4, shifted in x by a half each,
// and behind them a wide box whose front-top edge runs x −1 → 3 at z 0.8, y 6. Each box in front hides it
// by two surfaces (its front and back faces; its other faces are edge-on): x in [0, 0.5] behind the first
// box, [0.5, 1] the first and second, [1, 1.5] the second and third, [1.5, 2] the third.
TEST(OcclusionLevels, BoxesInARowByHand) {
  Scene scene;
  auto add = [&](const char* name, Solid s) {
    scene.objects.push_back({name, std::make_shared<const Solid>(std::move(s))});
  };
  add("a", gen::box({0, 0, 0}, {1, 1, 1}));
  add("b", gen::box({0.5, 2, 0}, {1.5, 3, 1}));
  add("c", gen::box({1, 4, 0}, {2, 5, 1}));
  add("back", gen::box({-1, 6, 0.2}, {3, 7, 0.8}));
  const Camera camera = ortho_camera(OrthoParameters{{1, -10, 0.5}, {1, 0, 0.5}, {0, 0, 1}, 8, 0});
  // The back box's edge from (−1, 6, 0.8) to (3, 6, 0.8).
  const Solid& back = *scene.objects[3].solid;
  std::uint32_t top_front = 0;
  bool found = false;
  for (std::uint32_t e = 0; e < back.edges.size(); ++e) {
    const Point3 a = back.vertices[back.edges[e].v0], b = back.vertices[back.edges[e].v1];
    if (a.y == 6 && b.y == 6 && a.z == 0.8 && b.z == 0.8) top_front = e, found = true;
  }
  ASSERT_TRUE(found);
  for (const unsigned max_level : {16u, 3u}) {
    HlrOptions options;
    options.max_level = max_level;
    const FrameResult result = render_frame(scene, camera, options);
    std::map<double, std::pair<double, int>> pieces;  // x0 → (x1, level)
    for (const VisibleSegment& s : result.segments)
      if (s.object == 3 && s.edge == top_front) {
        const double x0 = std::min(s.p0.x, s.p1.x), x1 = std::max(s.p0.x, s.p1.x);
        EXPECT_EQ(s.hidden, s.level > 0);
        pieces[x0] = {x1, s.level};
      }
    std::vector<std::tuple<double, double, int>> want = {
        {-1, 0, 0}, {0, 0.5, 2}, {0.5, 1.5, 4}, {1.5, 2, 2}, {2, 3, 0}};
    if (max_level < 4) want.erase(want.begin() + 2);
    ASSERT_EQ(pieces.size(), want.size()) << "max_level " << max_level;
    auto it = pieces.begin();
    for (const auto& [x0, x1, level] : want) {
      EXPECT_NEAR(it->first, x0, 1e-12);
      EXPECT_NEAR(it->second.first, x1, 1e-12);
      EXPECT_EQ(it->second.second, level) << "piece from x = " << x0;
      ++it;
    }
  }
}

// The visible pieces do not change when levels are counted (culling off then).
double visible_length(const FrameResult& r) {
  double sum = 0;
  for (const VisibleSegment& s : r.segments)
    if (!s.hidden) sum += distance(s.p0, s.p1);
  return sum;
}

struct Tally {
  int failed = 0;
  std::vector<std::size_t> per_level;
};

Tally check_views(const Scene& scene, Point3 center, double size, unsigned seed, int count,
                  unsigned max_level) {
  Tally t;
  t.per_level.assign(max_level + 1, 0);
  Rng r(seed);
  for (int n = 0; n < count; ++n) {
    const Camera camera = random_view(r, center, size, n);
    HlrOptions options;
    options.max_level = max_level;
    const FrameResult result = render_frame(scene, camera, options);
    const RayCaster oracle(scene, camera);
    const LevelReport levels = check_occlusion_levels(scene, oracle, result, max_level);
    const CheckReport visible = check_frame(scene, camera, result);
    const double plain = visible_length(render_frame(scene, camera));
    const double counted = visible_length(result);
    for (std::size_t k = 0; k <= max_level; ++k) t.per_level[k] += levels.samples_per_level[k];
    if (!levels.ok() || !visible.ok() || std::abs(plain - counted) > 1e-9 * std::max(plain, 1.0)) {
      ++t.failed;
      ADD_FAILURE() << "view " << n << " of seed " << seed << ": levels " << levels.summary() << "\nvisible "
                    << visible.summary() << "\nvisible length " << counted << " counted, " << plain
                    << " plain";
    }
  }
  return t;
}

TEST(OcclusionLevels, SpheresBehindEachOtherFromRandomViews) {
  Scene scene;
  for (int i = 0; i < 3; ++i)
    scene.objects.push_back(
        {"sphere", std::make_shared<const Solid>(gen::sphere({0.7 * i, 0.4 * i, 0.3 * i}, 0.6, 14, 8, 30))});
  const Tally t = check_views(scene, {0.7, 0.4, 0.3}, 1.6, 7, 40, 6);
  EXPECT_EQ(t.failed, 0);
  // The views reach deep: behind one sphere (2 surfaces) and two (4).
  EXPECT_GT(t.per_level[2], 100u);
  EXPECT_GT(t.per_level[4], 10u);
}

TEST(OcclusionLevels, InterpenetratingSolidsFromRandomViews) {
  // A torus through a box, a cylinder through both: intersection lines hidden at levels too.
  Scene scene;
  auto add = [&](const char* name, Solid s) {
    scene.objects.push_back({name, std::make_shared<const Solid>(std::move(s))});
  };
  add("torus", gen::torus({0, 0, 0}, 1, 0.35, 24, 10, 30));
  add("box", gen::box({-0.5, -1.6, -0.3}, {0.5, 1.6, 0.3}));
  add("post", gen::cylinder({0.9, 0, -1}, 0.2, 2, 12, 30));
  const Tally t = check_views(scene, {0, 0, 0}, 1.6, 11, 30, 8);
  EXPECT_EQ(t.failed, 0);
  EXPECT_GT(t.per_level[1], 50u);
  EXPECT_GT(t.per_level[3], 10u);
}

// The mesh scaled about the origin and moved, built again (a solid keeps its faces' planes).
Solid moved_and_scaled(const Solid& s, double scale, Vector3 offset) {
  std::vector<Point3> vertices = s.vertices;
  for (Point3& p : vertices) p = Point3{0, 0, 0} + (scale * (p - Point3{0, 0, 0}) + offset);
  return mesh_solid(vertices, triangles_of(s));
}

TEST(OcclusionLevels, SeparateSolidsFromRandomViews) {
  // Closed solids whose boxes meet no other's: their back faces are culled and each front face counts for
  // two surfaces; their back edges are examined and lie one surface nearer.
  Scene scene;
  auto add = [&](const char* name, Solid s) {
    scene.objects.push_back({name, std::make_shared<const Solid>(std::move(s))});
  };
  add("sphere", gen::sphere({0, 0, 0}, 0.6, 10, 6, 0));
  add("torus", gen::torus({1.6, 0.3, 0.2}, 0.6, 0.2, 14, 6, 0));
  add("block", gen::l_block({-1.9, -0.6, -0.5}, {1.2, 1, 1.1}, 0.4, 0.4));
  add("bumpy", moved_and_scaled(gen::closed_mesh(160, 9), 0.5, {0.2, 1.9, -0.3}));
  const Tally t = check_views(scene, {0, 0.4, 0}, 2.0, 13, 24, 8);
  EXPECT_EQ(t.failed, 0);
  EXPECT_GT(t.per_level[1], 20000u);  // back edges behind their own solid's front
  EXPECT_GT(t.per_level[3], 2000u);   // and behind another solid too
}

TEST(OcclusionLevels, OpenAndNonConvexMeshesFromRandomViews) {
  // An open box (one surface in front where it is open) and a generated closed mesh with pockets.
  Scene scene;
  scene.objects.push_back({"open", std::make_shared<const Solid>(gen::open_box({-1, -1, -1}, {1, 1, 1}))});
  scene.objects.push_back({"mesh", std::make_shared<const Solid>(gen::closed_mesh(300, 5))});
  const Tally t = check_views(scene, {0, 0, 0}, 1.5, 3, 30, 5);
  EXPECT_EQ(t.failed, 0);
  EXPECT_GT(t.per_level[1], 50u);
}

}  // namespace
}  // namespace hlr::test
