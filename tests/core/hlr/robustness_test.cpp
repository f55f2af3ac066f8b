// Inputs at the edges of double range must not crash the engine or leak non-finite numbers.
#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "stdlib/generators.hpp"

namespace hlr {
namespace {

void expect_finite(const FrameResult& r) {
  for (const VisibleSegment& s : r.segments) {
    EXPECT_TRUE(is_finite(s.p0) && is_finite(s.p1));
    EXPECT_TRUE(std::isfinite(s.s0.x + s.s0.y + s.s1.x + s.s1.y));
  }
}

TEST(EngineRobustness, CoordinatesNearTheTopOfDoubleRange) {
  // A box 1e150 across seen from 1e152 away: squares of these overflow, the engine must not use them.
  Scene scene;
  scene.objects.push_back({"huge", stdlib::box({-1e150, -1e150, -1e150}, {1e150, 1e150, 1e150})});
  scene.objects.push_back({"unit", stdlib::box({0, 0, 0}, {1, 1, 1})});
  for (const Camera& camera :
       {lookat_camera({{3e152, -2e152, 1e152}, {0, 0, 0}, {0, 0, 1}, 40, 0, 0}),
        ortho_camera({{3e152, -2e152, 1e152}, {0, 0, 0}, {0, 0, 1}, 1e151, 0})}) {
    const FrameResult r = render_frame(scene, camera);
    expect_finite(r);
    // The huge box shows its nine front edges; the unit box inside it is hidden.
    std::size_t huge = 0, unit = 0;
    for (const VisibleSegment& s : r.segments) (s.object == 0 ? huge : unit) += 1;
    EXPECT_EQ(huge, 9u) << camera.kind;
    EXPECT_EQ(unit, 0u) << camera.kind;
  }
}

TEST(EngineRobustness, EyeAlmostOnTheGeometryWithATinyNearPlane) {
  Scene scene;
  scene.objects.push_back({"box", stdlib::box({0, 0, 0}, {1, 1, 1})});
  // The eye 1e-300 above the top face: projections of nearby points exceed double range.
  const Camera camera = lookat_camera({{0.5, 0.5, 1 + 1e-300}, {0.5, 0.5, 0}, {0, 1, 0}, 90, 0, 1e-310});
  const FrameResult r = render_frame(scene, camera);
  expect_finite(r);
}

}  // namespace
}  // namespace hlr
