// Booleans (stdlib/booleans.hpp, issue 41): volumes against their analytic values, the drawing of a union
// against the same shape built by hand, the result against the ray-casting oracle from random views, and
// operands that cannot take part.
//   hlr_core_tests --gtest_filter='Boolean*'
#include "stdlib/booleans.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/camera/camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "stdlib/generators.hpp"
#include "tests/core/solid/solid_test_helpers.hpp"
#include "tests/support/mesh_views.hpp"
#include "tests/support/ray_caster_checks.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::test {
namespace {

namespace gen = hlr::stdlib;
using gen::BooleanOp;

// The enclosed volume (the divergence theorem over each face's fans).
double volume(const Solid& s) { return solid_test::signed_volume(s); }

double visible_length(const FrameResult& r) {
  double sum = 0;
  for (const VisibleSegment& s : r.segments)
    if (!s.hidden) sum += distance(s.p0, s.p1);
  return sum;
}

TEST(Boolean, VolumesOfBoxes) {
  const Solid a = gen::box({0, 0, 0}, {2, 2, 2}), b = gen::box({1, 1, 1}, {3, 3, 3});
  EXPECT_NEAR(volume(gen::boolean_solid(BooleanOp::Union, {&a, &b})), 8 + 8 - 1, 1e-12);
  EXPECT_NEAR(volume(gen::boolean_solid(BooleanOp::Difference, {&a, &b})), 8 - 1, 1e-12);
  EXPECT_NEAR(volume(gen::boolean_solid(BooleanOp::Intersection, {&a, &b})), 1, 1e-12);
  // Left to right: a minus b minus c.
  const Solid c = gen::box({-1, -1, -1}, {1, 1, 1});
  EXPECT_NEAR(volume(gen::boolean_solid(BooleanOp::Difference, {&a, &b, &c})), 8 - 1 - 1, 1e-12);
}

TEST(Boolean, DrilledPlateVolumeIsThePrisms) {
  // A plate minus a 24-sided cylinder through it: the plate's volume less the prism's (n/2·r²·sin(2π/n)·h).
  const Solid plate = gen::box({0, 0, 0}, {4, 3, 1});
  const Solid drill = gen::cylinder({2, 1.5, -1}, 0.8, 3, 24, 30);
  const Solid drilled = gen::boolean_solid(BooleanOp::Difference, {&plate, &drill});
  const double prism = 24.0 / 2 * 0.8 * 0.8 * std::sin(2 * std::acos(-1.0) / 24) * 1;
  EXPECT_NEAR(volume(drilled), 12 - prism, 1e-9);
  EXPECT_TRUE(drilled.closed);
}

TEST(Boolean, TwoBoxesSideBySideDrawAsOneBox) {
  // The union of two boxes sharing a face is the 4 × 2 × 1 box: no seam across its top or sides. Drawn
  // from random views it has the same visible length as the box built directly, piece for piece.
  const Solid a = gen::box({0, 0, 0}, {2, 2, 1}), b = gen::box({2, 0, 0}, {4, 2, 1});
  Scene joined, whole;
  joined.objects.push_back({"union", gen::boolean_solid(BooleanOp::Union, {&a, &b})});
  whole.objects.push_back({"box", gen::box({0, 0, 0}, {4, 2, 1})});
  Rng r(41);
  for (int n = 0; n < 12; ++n) {
    const Camera camera = random_view(r, {2, 1, 0.5}, 4.5, n);
    const FrameResult got = render_frame(joined, camera), want = render_frame(whole, camera);
    EXPECT_NEAR(visible_length(got), visible_length(want), 1e-9 * visible_length(want)) << "view " << n;
  }
}

TEST(Boolean, ResultsAreExactFromRandomViews) {
  // A drilled, slotted plate; a torus through a box, intersected; a union of a sphere and a cylinder: the
  // ray-casting oracle finds nothing drawn hidden and nothing visible missing.
  const Solid plate = gen::box({0, 0, 0}, {4, 3, 1});
  const Solid drill = gen::cylinder({1.2, 1.5, -1}, 0.5, 3, 16, 30);
  const Solid slot = gen::box({2.5, -1, 0.5}, {3.2, 4, 2});
  const Solid torus = gen::torus({0, 0, 0}, 1, 0.4, 20, 10, 30);
  const Solid cube = gen::box({-0.7, -1.6, -0.6}, {0.7, 1.6, 0.6});
  const Solid sphere = gen::sphere({0, 0, 0}, 0.8, 16, 8, 30);
  const Solid post = gen::cylinder({0, 0, -1.5}, 0.3, 3, 12, 30);
  Scene scene;
  scene.objects.push_back({"plate", gen::boolean_solid(BooleanOp::Difference, {&plate, &drill, &slot})});
  Solid ring = gen::boolean_solid(BooleanOp::Intersection, {&torus, &cube});
  scene.objects.push_back({"ring", ring.transformed(Affine3::translation({-2.5, 0, 0}))});
  Solid knob = gen::boolean_solid(BooleanOp::Union, {&sphere, &post});
  scene.objects.push_back({"knob", knob.transformed(Affine3::translation({1, -2.5, 0}))});
  Rng r(4141);
  int failed = 0;
  for (int n = 0; n < 16; ++n) {
    const Camera camera = random_view(r, {0.5, 0, 0}, 4.5, n);
    const CheckReport report = check_frame(scene, camera, render_frame(scene, camera));
    if (!report.ok()) {
      ++failed;
      ADD_FAILURE() << "view " << n << ": " << report.summary();
    }
  }
  EXPECT_EQ(failed, 0);
}

TEST(Boolean, OperandsThatCannotTakePartAreNamed) {
  const Solid a = gen::box({0, 0, 0}, {1, 1, 1});
  const Solid open = gen::open_box({0.5, 0.5, 0.5}, {2, 2, 2});
  try {
    gen::boolean_solid(BooleanOp::Union, {&a, &open});
    FAIL() << "an open operand was taken";
  } catch (const gen::BooleanOperandError& e) {
    EXPECT_EQ(e.operand, 1u);
    EXPECT_NE(std::string(e.what()).find("not closed"), std::string::npos) << e.what();
  }
  // Two boxes welded into one mesh that passes through itself.
  const Solid b = gen::box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5});
  std::vector<Point3> vertices = a.vertices;
  vertices.insert(vertices.end(), b.vertices.begin(), b.vertices.end());
  std::vector<std::vector<VertexIndex>> faces = triangles_of(a);
  for (auto f : triangles_of(b)) {
    for (auto& v : f) v += static_cast<VertexIndex>(a.vertices.size());
    faces.push_back(f);
  }
  const Solid crossing = mesh_solid(vertices, faces);
  try {
    gen::boolean_solid(BooleanOp::Difference, {&a, &crossing});
    FAIL() << "a self-crossing operand was taken";
  } catch (const gen::BooleanOperandError& e) {
    EXPECT_EQ(e.operand, 1u);
    EXPECT_NE(std::string(e.what()).find("crosses itself"), std::string::npos) << e.what();
  }
  // Nothing in common.
  const Solid far = gen::box({5, 5, 5}, {6, 6, 6});
  EXPECT_THROW(gen::boolean_solid(BooleanOp::Intersection, {&a, &far}), std::runtime_error);
}

}  // namespace
}  // namespace hlr::test
