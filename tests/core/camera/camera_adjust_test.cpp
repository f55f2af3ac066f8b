// adjust(): Albers' keys for any camera, checked against the eye and view direction worked by hand.
#include "core/camera/camera_adjust.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/camera/camera_error.hpp"
#include "core/camera/lookat_camera.hpp"

namespace hlr {
namespace {

Camera from_x() { return lookat_camera({{10, 0, 0}, {0, 0, 0}, {0, 0, 1}, 40, 0, 0}); }

void expect_near(Point3 a, Point3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-9);
  EXPECT_NEAR(a.y, b.y, 1e-9);
  EXPECT_NEAR(a.z, b.z, 1e-9);
}

TEST(CameraAdjust, ThetaAndPhiOrbitAboutThePivotDollyMovesTheEye) {
  const Camera c = from_x();
  CameraAdjustment a;
  a.theta_deg = 90;  // from +x round to +y, seen from above counter-clockwise
  const Camera turned = adjusted_camera(c, a);
  expect_near(turned.eye_world(), {0, 10, 0});
  const Vector3 d = turned.direction_world();
  expect_near({d.x, d.y, d.z}, {0, -1, 0});
  a.phi_deg = 30;  // then up by 30°: (0, 10 cos 30°, 10 sin 30°)
  expect_near(adjusted_camera(c, a).eye_world(), {0, 10 * std::cos(std::numbers::pi / 6), 5});
  a.dolly = 1;  // one unit nearer the pivot, along the view
  expect_near(adjusted_camera(c, a).eye_world(), {0, 9 * std::cos(std::numbers::pi / 6), 4.5});
  // About another pivot: the eye keeps its distance from it.
  CameraAdjustment b;
  b.theta_deg = 180;
  b.pivot = {5, 0, 0};
  expect_near(adjusted_camera(c, b).eye_world(), {0, 0, 0});
}

TEST(CameraAdjust, ZoomScalesThePictureAndNothingElse) {
  const Camera c = from_x();
  CameraAdjustment a;
  a.zoom = 2;
  const Camera z = adjusted_camera(c, a);
  EXPECT_DOUBLE_EQ(z.focal, 2 * c.focal);
  const Point2 p = c.project({0, 1, 1}), q = z.project({0, 1, 1});
  EXPECT_NEAR(q.x, 2 * p.x, 1e-12);
  EXPECT_NEAR(q.y, 2 * p.y, 1e-12);
  // No adjustment: the same picture.
  const Point2 r = adjusted_camera(c, {}).project({1, 2, 3}), s = c.project({1, 2, 3});
  EXPECT_NEAR(r.x, s.x, 1e-12);
  EXPECT_NEAR(r.y, s.y, 1e-12);
}

TEST(CameraAdjust, BadValuesNameTheirParameter) {
  CameraAdjustment a;
  a.zoom = 0;
  try {
    adjusted_camera(from_x(), a);
    FAIL();
  } catch (const CameraError& e) {
    EXPECT_EQ(e.parameter, "zoom");
    EXPECT_STREQ(e.what(), "bad argument 'zoom' to adjust(): must be finite and positive");
  }
  CameraAdjustment b;
  b.theta_deg = std::nan("");
  EXPECT_THROW(adjusted_camera(from_x(), b), CameraError);
}

}  // namespace
}  // namespace hlr
