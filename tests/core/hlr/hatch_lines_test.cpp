// Hatch lines through the engine (tracker issue 36): drawn exactly where visible, like markings, checked
// against the ray-casting oracle from random views; never drawn hidden; and they change nothing else.
//   hlr_core_tests --gtest_filter='HatchLines*'
#include <gtest/gtest.h>

#include <memory>

#include "core/hlr/render_frame.hpp"
#include "core/solid/hatching.hpp"
#include "stdlib/generators.hpp"
#include "tests/support/mesh_views.hpp"
#include "tests/support/ray_caster_checks.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::test {
namespace {

namespace gen = hlr::stdlib;

Scene hatched_scene() {
  Scene scene;
  auto add = [&](const char* name, const Solid& s, HatchSpec spec) {
    scene.objects.push_back({name, std::make_shared<const Solid>(hatched(s, spec))});
  };
  HatchSpec lit;
  lit.spacing = 0.12;
  lit.light = Vector3{1, -2, 3};
  add("sphere", gen::sphere({0, 0, 0}, 0.7, 14, 8, 30), lit);
  HatchSpec crossed;
  crossed.spacing = 0.15;
  crossed.angle_deg = 30;
  crossed.cross = true;
  add("block", gen::l_block({0.4, -0.9, -0.6}, {1.4, 1.1, 1.2}, 0.5, 0.45), crossed);
  HatchSpec plain;
  plain.spacing = 0.1;
  plain.angle_deg = 70;
  HatchSpec sliced;  // lines that run on across faces
  sliced.spacing = 0.08;
  sliced.planes = Vector3{0.3, -0.5, 1};
  sliced.light = Vector3{-1, 0, 1};
  add("torus", gen::torus({-0.6, 0.9, 0.1}, 0.6, 0.2, 16, 8, 30), sliced);
  // Open and concave: a box without its top, hatched inside and out.
  add("tray", gen::open_box({-1.6, -1.2, -0.7}, {-0.6, -0.3, -0.2}), plain);
  return scene;
}

double length_of(const FrameResult& r, bool hatch) {
  double sum = 0;
  for (const VisibleSegment& s : r.segments)
    if (!s.hidden && s.hatch == hatch) sum += distance(s.p0, s.p1);
  return sum;
}

TEST(HatchLines, ExactFromRandomViews) {
  const Scene scene = hatched_scene();
  Scene bare;
  for (const SceneObject& o : scene.objects) {
    Solid s = *o.solid;
    std::erase_if(s.edges, [](const SolidEdge& e) { return e.kind == EdgeKind::Hatch; });
    bare.objects.push_back({o.name, std::move(s)});
  }
  Rng r(36);
  int failed = 0;
  double hatch_drawn = 0;
  for (int n = 0; n < 16; ++n) {
    const Camera camera = random_view(r, {0, 0, 0}, 2.2, n);
    const FrameResult result = render_frame(scene, camera);
    const CheckReport report = check_frame(scene, camera, result);
    if (!report.ok()) {
      ++failed;
      ADD_FAILURE() << "view " << n << ": " << report.summary();
    }
    hatch_drawn += length_of(result, true);
    // Hatching hides nothing: the rest of the drawing is what it is without it.
    const FrameResult plain = render_frame(bare, camera);
    EXPECT_NEAR(length_of(result, false), length_of(plain, false),
                1e-9 * std::max(1.0, length_of(plain, false)))
        << "view " << n;
  }
  EXPECT_EQ(failed, 0);
  EXPECT_GT(hatch_drawn, 10.0);
}

TEST(HatchLines, NeverDrawnHidden) {
  const Scene scene = hatched_scene();
  Rng r(41);
  for (int n = 0; n < 6; ++n) {
    const Camera camera = random_view(r, {0, 0, 0}, 2.2, n);
    for (const unsigned levels : {0u, 3u}) {
      HlrOptions options;
      options.include_hidden = true;
      options.max_level = levels;
      const FrameResult result = render_frame(scene, camera, options);
      std::size_t hidden = 0, hatch = 0;
      for (const VisibleSegment& s : result.segments) {
        hidden += s.hidden;
        hatch += s.hatch;
        EXPECT_FALSE(s.hidden && s.hatch) << "view " << n;
        if (s.hatch) {
          EXPECT_EQ(scene.objects[s.object].solid->edges[s.edge].kind, EdgeKind::Hatch);
        }
      }
      EXPECT_GT(hidden, 0u);
      EXPECT_GT(hatch, 0u);
    }
  }
}

}  // namespace
}  // namespace hlr::test
