// Each line once: visible pieces that earlier pieces on the same line cover (solids sharing an edge
// line) are left out of the engine's result (core/hlr/coincident_pieces.hpp), so the segments are the
// drawing the plotter draws.
#include "core/hlr/coincident_pieces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "stdlib/generators.hpp"
#include "tests/support/ray_caster_checks.hpp"

namespace hlr {
namespace {

// World points come back from view space: equal to the data within rounding.
bool near(double a, double b) { return std::abs(a - b) < 1e-12; }

Camera view() { return lookat_camera(LookatParameters{{3, -2, 2.5}, {0.5, 0.5, 0.5}, {0, 0, 1}, 40, 0, 0}); }

std::size_t visible(const FrameResult& r) {
  std::size_t n = 0;
  for (const VisibleSegment& s : r.segments) n += !s.hidden;
  return n;
}

// Fifty identical unit cubes in one place: the nine edges seen, once each (before: 450 pieces).
TEST(CoincidentPieces, FiftyIdenticalCubesAreNineLines) {
  Scene scene;
  for (int i = 0; i < 50; ++i)
    scene.objects.push_back({"cube" + std::to_string(i), stdlib::box({0, 0, 0}, {1, 1, 1})});
  const FrameResult r = render_frame(scene, view());
  ASSERT_EQ(r.segments.size(), 9u);
  EXPECT_EQ(r.stats.visible_segments, 9u);
  for (const VisibleSegment& s : r.segments) EXPECT_EQ(s.object, 0u);  // the first cube's
  HlrOptions each;
  each.coincident_once = false;
  EXPECT_EQ(render_frame(scene, view(), each).segments.size(), 450u);
  const test::CheckReport report = test::check_frame(scene, view(), r);
  EXPECT_TRUE(report.ok()) << report.summary();
}

// A small box on a big one, flush with its front: the small box's front bottom edge lies within the big
// box's front top edge and is left out; the big box's edge stays whole. A box whose edge only partly
// overlaps another's keeps it whole (the plotter's planner merges what overlaps).
TEST(CoincidentPieces, CoveredWhollyIsLeftOutPartlyIsKept) {
  Scene scene;
  scene.objects.push_back({"big", stdlib::box({0, 0, 0}, {2, 1, 1})});
  scene.objects.push_back({"small", stdlib::box({0.5, 0, 1}, {1.2, 0.6, 1.4})});
  const Camera camera = lookat_camera(LookatParameters{{3, -5, 4}, {1, 0.5, 0.8}, {0, 0, 1}, 40, 0, 0});
  const FrameResult r = render_frame(scene, camera);
  bool small_front_bottom = false, big_front_top = false;
  for (const VisibleSegment& s : r.segments) {
    const bool front_top = near(s.p0.y, 0) && near(s.p1.y, 0) && near(s.p0.z, 1) && near(s.p1.z, 1);
    if (front_top && s.object == 1) small_front_bottom = true;
    if (front_top && s.object == 0 && near(std::abs(s.p1.x - s.p0.x), 2)) big_front_top = true;
  }
  EXPECT_FALSE(small_front_bottom);
  EXPECT_TRUE(big_front_top);

  EXPECT_TRUE(test::check_frame(scene, camera, r).ok()) << test::check_frame(scene, camera, r).summary();

  Scene partly;
  partly.objects.push_back({"left", stdlib::box({0, 0, 0}, {2, 1, 1})});
  partly.objects.push_back({"right", stdlib::box({1, 0, 1}, {3, 1, 2})});  // its bottom front edge runs past
  const FrameResult p = render_frame(partly, camera);
  bool right_bottom_front = false;
  for (const VisibleSegment& s : p.segments)
    if (s.object == 1 && near(s.p0.y, 0) && near(s.p1.y, 0) && near(s.p0.z, 1) && near(s.p1.z, 1) &&
        near(std::abs(s.p1.x - s.p0.x), 2))
      right_bottom_front = true;
  EXPECT_TRUE(right_bottom_front);
}

// The hidden layer is left as it is, and what is visible is the same with and without it.
TEST(CoincidentPieces, HiddenLayerUntouched) {
  Scene scene;
  for (int i = 0; i < 3; ++i)
    scene.objects.push_back({"cube" + std::to_string(i), stdlib::box({0, 0, 0}, {1, 1, 1})});
  HlrOptions with_hidden;
  with_hidden.include_hidden = true;
  const FrameResult r = render_frame(scene, view(), with_hidden);
  EXPECT_EQ(visible(r), 9u);
  EXPECT_EQ(r.segments.size() - visible(r), 3u * 3u);  // each cube's three hidden edges
}

// remove_covered_pieces on hand-made pieces: a piece covered by two earlier ones end to end goes; one with
// a gap between them stays; the earlier of two identical pieces stays.
TEST(CoincidentPieces, CoveredByTwoEarlierPieces) {
  auto piece = [](double a, double b, std::uint32_t object) {
    VisibleSegment s;
    s.p0 = {a, 0, 0}, s.p1 = {b, 0, 0};
    s.s0 = {a, 0}, s.s1 = {b, 0};
    s.object = object;
    return s;
  };
  std::vector<VisibleSegment> pieces = {piece(0, 1, 0),   piece(1, 2, 1),     piece(0.5, 1.5, 2),
                                        piece(2.5, 3, 3), piece(1.8, 2.7, 4), piece(2.5, 3, 5)};
  EXPECT_EQ(remove_covered_pieces(pieces), 2u);
  ASSERT_EQ(pieces.size(), 4u);
  EXPECT_EQ(pieces[0].object, 0u);
  EXPECT_EQ(pieces[1].object, 1u);
  EXPECT_EQ(pieces[2].object, 3u);
  EXPECT_EQ(pieces[3].object, 4u);  // [1.8, 2.7] has a gap (2, 2.5) that nothing earlier covers
}

}  // namespace
}  // namespace hlr
