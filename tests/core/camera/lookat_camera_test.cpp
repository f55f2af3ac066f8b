#include "core/camera/lookat_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/camera/camera_error.hpp"

namespace hlr {
namespace {

const LookatParameters kBasic{.eye = {3, -10, 2}, .target = {1, 4, -1}, .up = {0, 0, 1}, .fov_deg = 50};

TEST(LookatCamera, ContractFields) {
  const Camera c = lookat_camera(kBasic);
  EXPECT_EQ(c.kind, "lookat");
  EXPECT_EQ(c.projection, Projection::Perspective);
  EXPECT_NEAR(c.focal, 1 / std::tan(25 * std::numbers::pi / 180), 1e-15);
  EXPECT_FALSE(c.frame.has_value());
  EXPECT_NEAR(c.near_depth, 1e-4 * distance(kBasic.eye, kBasic.target), 1e-18);
  const Point3 eye = c.eye_world();
  EXPECT_NEAR(eye.x, 3, 1e-12);
  EXPECT_NEAR(eye.y, -10, 1e-12);
  EXPECT_NEAR(eye.z, 2, 1e-12);
  const Vector3 d = c.direction_world(), want = normalize(kBasic.target - kBasic.eye);
  EXPECT_NEAR(d.x, want.x, 1e-12);
  EXPECT_NEAR(d.y, want.y, 1e-12);
  EXPECT_NEAR(d.z, want.z, 1e-12);
}

TEST(LookatCamera, PointOnAxisProjectsToCentre) {
  const Camera c = lookat_camera(kBasic);
  for (const double t : {0.5, 1.0, 7.0}) {
    const Point3 q = lerp(kBasic.eye, kBasic.target, t);
    const Point2 picture = c.project(q);
    EXPECT_NEAR(picture.x, 0, 1e-12);
    EXPECT_NEAR(picture.y, 0, 1e-12);
    EXPECT_NEAR(c.view(q).z, t * distance(kBasic.eye, kBasic.target), 1e-12);
  }
}

TEST(LookatCamera, TopOfFieldOfViewProjectsToOne) {
  // Looking along +y with z up: the top edge of a 60° field of view is 30° above the axis.
  const Camera c = lookat_camera({.eye = {0, 0, 0}, .target = {0, 5, 0}, .fov_deg = 60});
  const double depth = 8;
  const Point2 top = c.project({0, depth, depth * std::tan(std::numbers::pi / 6)});
  EXPECT_NEAR(top.x, 0, 1e-12);
  EXPECT_NEAR(top.y, 1, 1e-12);
  const Point2 bottom = c.project({0, depth, -depth * std::tan(std::numbers::pi / 6)});
  EXPECT_NEAR(bottom.y, -1, 1e-12);
}

TEST(LookatCamera, RightHanded) {
  // From −y looking toward +y with z up, +x is to the viewer's right.
  const Camera c = lookat_camera({.eye = {0, -10, 0}, .target = {0, 0, 0}});
  EXPECT_GT(c.project({1, 0, 0}).x, 0);
  EXPECT_NEAR(c.project({1, 0, 0}).y, 0, 1e-12);
  EXPECT_GT(c.project({0, 0, 1}).y, 0);
  // The up hint only needs to be roughly up: it is re-orthogonalised.
  const Camera tilted = lookat_camera({.eye = {0, -10, 0}, .target = {0, 0, 0}, .up = {0, 3, 1}});
  EXPECT_NEAR(tilted.project({1, 0, 0}).x, c.project({1, 0, 0}).x, 1e-12);
  EXPECT_NEAR(tilted.project({0, 0, 1}).y, c.project({0, 0, 1}).y, 1e-12);
}

TEST(LookatCamera, AspectFrameAndNear) {
  const Camera c = lookat_camera({.eye = {0, -10, 0}, .target = {0, 0, 0}, .aspect = 1.5, .near = 0.25});
  ASSERT_TRUE(c.frame.has_value());
  EXPECT_EQ(c.frame->xmin, -1.5);
  EXPECT_EQ(c.frame->xmax, 1.5);
  EXPECT_EQ(c.frame->ymin, -1);
  EXPECT_EQ(c.frame->ymax, 1);
  EXPECT_EQ(c.near_depth, 0.25);
}

std::string parameter_of(const LookatParameters& p) {
  try {
    lookat_camera(p);
  } catch (const CameraError& e) {
    EXPECT_NE(std::string(e.what()).find("to lookat()"), std::string::npos) << e.what();
    return e.parameter;
  }
  return "(none)";
}

TEST(LookatCamera, RejectsBadParameters) {
  const Point3 e{0, -10, 0}, t{0, 0, 0};
  EXPECT_EQ(parameter_of({.eye = e, .target = e}), "target");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .up = {0, 2, 0}}), "up");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .up = {0, -1, 0}}), "up");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .up = {0, 0, 0}}), "up");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .fov_deg = 0}), "fov");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .fov_deg = 180}), "fov");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .fov_deg = -10}), "fov");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .fov_deg = NAN}), "fov");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .aspect = -1}), "aspect");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .near = -1}), "near");
  EXPECT_EQ(parameter_of({.eye = {NAN, 0, 0}, .target = t}), "eye");
  EXPECT_EQ(parameter_of({.eye = e, .target = {0, INFINITY, 0}}), "target");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .up = {NAN, 0, 1}}), "up");
  EXPECT_EQ(parameter_of({.eye = e, .target = t}), "(none)");
}

TEST(LookatCamera, ErrorMessages) {
  const auto message = [](const LookatParameters& p) {
    try {
      lookat_camera(p);
    } catch (const CameraError& e) {
      return std::string(e.what());
    }
    return std::string("(none)");
  };
  EXPECT_EQ(message({.eye = {0, -10, 0}, .target = {}, .fov_deg = 190}),
            "bad argument 'fov' to lookat(): must be between 0 and 180 degrees (got 190)");
  EXPECT_EQ(message({.eye = {0, -10, 0}, .target = {}, .up = {0, 1, 0}}),
            "bad argument 'up' to lookat(): parallel to the viewing direction");
}

}  // namespace
}  // namespace hlr
