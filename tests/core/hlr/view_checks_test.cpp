// check_view() and point_inside_closed_solid(): the eye inside a closed solid, and a near plane that cuts
// away most of the scene, against answers worked out by hand for boxes and a torus-like ring.
#include "core/hlr/view_checks.hpp"

#include <gtest/gtest.h>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "stdlib/generators.hpp"

namespace hlr {
namespace {

TEST(ViewChecks, PointsInsideAClosedSolid) {
  const Solid box = stdlib::box({0, 0, 0}, {4, 2, 1});
  EXPECT_TRUE(point_inside_closed_solid(box, {1, 1, 0.5}));
  EXPECT_TRUE(point_inside_closed_solid(box, {3.999, 1.999, 0.999}));
  EXPECT_FALSE(point_inside_closed_solid(box, {5, 1, 0.5}));
  EXPECT_FALSE(point_inside_closed_solid(box, {2, 1, 1.001}));
  // A ray from the centre along a face diagonal of a cube meets edges: the next direction decides.
  const Solid cube = stdlib::box({-1, -1, -1}, {1, 1, 1});
  EXPECT_TRUE(point_inside_closed_solid(cube, {0, 0, 0}));
  // A prism with a square hole: the hole is outside, the wall inside.
  const Solid ring =
      stdlib::prism({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}, {{{-1, -1}, {-1, 1}, {1, 1}, {1, -1}}}, 0, 1);
  EXPECT_FALSE(point_inside_closed_solid(ring, {0, 0, 0.5}));
  EXPECT_TRUE(point_inside_closed_solid(ring, {1.5, 0, 0.5}));
}

TEST(ViewChecks, TheEyeInsideAClosedSolid) {
  Scene scene;
  scene.objects.emplace_back("far", stdlib::box({10, 10, 0}, {11, 11, 1}));
  scene.objects.emplace_back("room", stdlib::box({-5, -5, 0}, {5, 5, 3}));
  LookatParameters inside;
  inside.eye = {0, 0, 1.5};
  inside.target = {4, 0, 1.5};
  EXPECT_EQ(check_view(scene, lookat_camera(inside)).eye_inside, 1u);
  LookatParameters outside = inside;
  outside.eye = {-9, 0, 1.5};
  EXPECT_FALSE(check_view(scene, lookat_camera(outside)).eye_inside.has_value());
}

TEST(ViewChecks, ANearPlaneCuttingMostOfTheScene) {
  Scene scene;
  scene.objects.emplace_back("box", stdlib::box({0, 0, 0}, {10, 10, 10}));
  LookatParameters p;
  p.eye = {-20, 5, 5};
  p.target = {0, 5, 5};
  // The box's near face is 20 away, its far face 30: a near plane at 25 cuts off half the corners, at 35
  // all of them.
  p.near = 25;
  ViewProblems half = check_view(scene, lookat_camera(p));
  EXPECT_EQ(half.vertices_in_front, 8u);
  EXPECT_EQ(half.vertices_cut_away, 4u);
  EXPECT_FALSE(half.near_plane_cuts_most());
  p.near = 35;
  EXPECT_TRUE(check_view(scene, lookat_camera(p)).near_plane_cuts_most());
  p.near = 0;  // the default: a tiny fraction of the distance to the target
  EXPECT_EQ(check_view(scene, lookat_camera(p)).vertices_cut_away, 0u);
  // Orthographic cameras have no near plane and no eye point.
  OrthoParameters o;
  o.eye = {5, 5, 5};
  o.target = {5, 5, 0};
  o.up = {0, 1, 0};
  o.height = 20;
  const ViewProblems ortho = check_view(scene, ortho_camera(o));
  EXPECT_FALSE(ortho.eye_inside.has_value());
  EXPECT_FALSE(ortho.near_plane_cuts_most());
}

}  // namespace
}  // namespace hlr
