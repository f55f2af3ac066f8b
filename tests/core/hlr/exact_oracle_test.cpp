// The exact oracle (tests/support/exact_oracle) checked before it judges: it must notice a drawing with
// pieces dropped, intersection lines left out or hidden pieces shown, and it must agree with the tolerant
// ray caster — an independent computation in floating point — wherever that one decides.
//   hlr_core_tests --gtest_filter='ExactOracle*'
#include "tests/support/exact_oracle.hpp"

#include <gtest/gtest.h>

#include <memory>

#include "core/camera/lookat_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "stdlib/generators.hpp"
#include "tests/support/mesh_views.hpp"
#include "tests/support/ray_caster.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::test {
namespace {

// Three boxes as triangle meshes, a bar piercing the other two.
Scene three_boxes() {
  Scene scene;
  auto add = [&](const char* name, Point3 lo, Point3 hi) {
    const Solid box = stdlib::box(lo, hi);
    scene.objects.push_back(
        {name, std::make_shared<const Solid>(mesh_solid(box.vertices, triangles_of(box)))});
  };
  add("front", {0, 0, 0}, {2, 2, 2});
  add("back", {-3, 3, 0}, {3, 5, 3});
  add("bar", {1, -1, 0.5}, {1.5, 4, 1});
  return scene;
}

TEST(ExactOracle, CatchesInjectedErrors) {
  const Scene scene = three_boxes();
  const Camera camera = lookat_camera(LookatParameters{{4, -8, 5}, {0, 2, 1}, {0, 0, 1}, 45, 0, 0});
  HlrOptions with_hidden;
  with_hidden.include_hidden = true;
  const FrameResult full = render_frame(scene, camera, with_hidden);
  FrameResult visible;
  for (const auto& s : full.segments)
    if (!s.hidden) visible.segments.push_back(s);
  const ExactReport clean = check_exact(scene, camera, visible);
  ASSERT_TRUE(clean.ok()) << clean.summary();
  EXPECT_GT(clean.crossing_visible, 10u) << "the bar should cross the boxes where it is seen";

  int dropped = 0;  // 1. any edge piece longer than a tenth of the scene, left out
  for (std::size_t i = 0; i < visible.segments.size(); ++i) {
    const auto& s = visible.segments[i];
    if (s.source != SegmentSource::Edge || distance(s.p0, s.p1) < 1) continue;
    FrameResult broken = visible;
    broken.segments.erase(broken.segments.begin() + static_cast<std::ptrdiff_t>(i));
    EXPECT_GT(check_exact(scene, camera, broken).edge_missing, 0u)
        << "dropping segment " << i << " went unnoticed";
    ++dropped;
  }
  EXPECT_GT(dropped, 5);
  FrameResult no_lines;  // 2. the intersection lines, left out
  for (const auto& s : visible.segments)
    if (s.source == SegmentSource::Edge) no_lines.segments.push_back(s);
  ASSERT_LT(no_lines.segments.size(), visible.segments.size());
  EXPECT_GT(check_exact(scene, camera, no_lines).crossing_missing, 0u);
  int shown = 0;  // 3. a hidden piece longer than a tenth of the scene, drawn
  for (const auto& s : full.segments) {
    if (!s.hidden || distance(s.p0, s.p1) < 1) continue;
    FrameResult wrong = visible;
    wrong.segments.push_back(s);
    wrong.segments.back().hidden = false;
    EXPECT_GT(check_exact(scene, camera, wrong).drawn_hidden, 0u) << "a hidden piece shown went unnoticed";
    ++shown;
  }
  EXPECT_GT(shown, 3);
}

TEST(ExactOracle, AgreesWithTheRayCasterWhereItDecides) {
  const Scene scene = three_boxes();
  Rng r(77);
  int decided = 0, hidden = 0;
  for (int n = 0; n < 12; ++n) {
    const Camera camera = random_view(r, {0, 2, 1.5}, 4, n);
    const ExactOracle exact_oracle(scene, camera);
    const RayCaster ray_caster(scene, camera);
    for (int k = 0; k < 400; ++k) {
      // Points on the boxes' edges (where drawings are judged) and anywhere in the scene.
      Point3 p;
      if (k % 2 == 0) {
        const Solid& s = *scene.objects[static_cast<std::size_t>(r.integer(0, 2))].solid;
        const SolidEdge& e =
            s.edges[static_cast<std::size_t>(r.integer(0, static_cast<int>(s.edges.size()) - 1))];
        p = lerp(s.vertices[e.v0], s.vertices[e.v1], r(0, 1));
      } else {
        p = r.point({-3, -1, 0}, {3, 5, 3});
      }
      const Visibility loose = ray_caster.visibility(p);
      if (loose == Visibility::Ambiguous) continue;
      ++decided;
      hidden += loose == Visibility::Hidden;
      EXPECT_EQ(exact_oracle.visibility(exact(p)), loose) << "view " << n << ", point " << k;
    }
  }
  EXPECT_GT(decided, 3000);
  EXPECT_GT(hidden, 1000);
}

}  // namespace
}  // namespace hlr::test
