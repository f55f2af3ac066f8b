// follow(): the eye on the path, looking along it, and leaning into turns only.
#include "core/camera/follow_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/camera_error.hpp"

namespace hlr {
namespace {

TEST(FollowCamera, LooksAlongAStraightPath) {
  FollowParameters p;
  p.path = {{0, 0, 0}, {10, 0, 0}};
  p.t = 0.5;
  p.bank_deg = 30;  // a straight path never turns: no roll
  const Camera c = follow_camera(p);
  EXPECT_EQ(c.kind, "follow");
  const Point3 ahead = c.viewFromWorld.apply(Point3{6, 0, 0});  // 1 ahead of the eye at (5, 0, 0)
  EXPECT_NEAR(ahead.x, 0, 1e-12);
  EXPECT_NEAR(ahead.y, 0, 1e-12);
  EXPECT_NEAR(ahead.z, 1, 1e-12);
  const Point3 above = c.viewFromWorld.apply(Point3{5, 0, 1});  // straight up is straight up
  EXPECT_NEAR(above.x, 0, 1e-12);
  EXPECT_NEAR(above.y, 1, 1e-12);
}

TEST(FollowCamera, BanksIntoATurn) {
  // A quarter circle turning left (counter-clockwise seen from above), sampled evenly.
  FollowParameters p;
  for (int k = 0; k <= 8; ++k) {
    const double a = M_PI / 2 * k / 8;
    p.path.push_back({100 * std::sin(a), 100 - 100 * std::cos(a), 0});
  }
  p.t = 0.5;
  p.bank_deg = 20;
  const Camera c = follow_camera(p);
  // The world's up seen by the camera leans to the right of the picture as the camera rolls left:
  // its x in view space is positive, and the roll is at most the 20° asked for.
  const Vector3 up = c.viewFromWorld.apply(Vector3{0, 0, 1});
  EXPECT_GT(up.x, 0.05);
  EXPECT_LE(std::atan2(up.x, up.y), 20 * M_PI / 180 + 1e-9);
  p.bank_deg = -20;  // the other way
  EXPECT_LT(follow_camera(p).viewFromWorld.apply(Vector3{0, 0, 1}).x, -0.05);
}

TEST(FollowCamera, BadPathsNameTheParameter) {
  FollowParameters p;
  p.path = {{0, 0, 0}};
  EXPECT_THROW(follow_camera(p), CameraError);
  p.path = {{1, 2, 3}, {1, 2, 3}};
  try {
    follow_camera(p);
    FAIL();
  } catch (const CameraError& e) {
    EXPECT_EQ(e.parameter, "path");
  }
}

}  // namespace
}  // namespace hlr
