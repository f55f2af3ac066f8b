#include "core/camera/ortho_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/camera/camera_error.hpp"

namespace hlr {
namespace {

TEST(OrthoCamera, ContractFields) {
  const Camera c = ortho_camera({.eye = {0, -10, 0}, .target = {0, 0, 0}, .height = 4, .aspect = 2});
  EXPECT_EQ(c.kind, "ortho");
  EXPECT_EQ(c.projection, Projection::Orthographic);
  EXPECT_DOUBLE_EQ(c.focal, 0.5);
  ASSERT_TRUE(c.frame.has_value());
  EXPECT_EQ(c.frame->xmin, -2);
  EXPECT_EQ(c.frame->xmax, 2);
  EXPECT_EQ(c.frame->ymin, -1);
  EXPECT_EQ(c.frame->ymax, 1);
  const Vector3 d = c.direction_world();
  EXPECT_NEAR(d.x, 0, 1e-15);
  EXPECT_NEAR(d.y, 1, 1e-15);
  EXPECT_NEAR(d.z, 0, 1e-15);
}

TEST(OrthoCamera, HeightMapsToUnitPictureAndDepthDoesNotScale) {
  const Camera c = ortho_camera({.eye = {0, -10, 0}, .target = {0, 0, 0}, .height = 4});
  EXPECT_FALSE(c.frame.has_value());
  for (const double y : {-5.0, 0.0, 30.0}) {
    const Point2 top = c.project({0, y, 2});
    EXPECT_NEAR(top.x, 0, 1e-12);
    EXPECT_NEAR(top.y, 1, 1e-12);
    const Point2 right = c.project({3, y, -2});
    EXPECT_NEAR(right.x, 1.5, 1e-12);  // right-handed: +x is to the right seen from −y
    EXPECT_NEAR(right.y, -1, 1e-12);
  }
  // Depth still grows away from the eye (ordering for hidden lines).
  EXPECT_LT(c.view({0, 0, 0}).z, c.view({0, 5, 0}).z);
}

TEST(OrthoCamera, RejectsBadParameters) {
  const auto parameter_of = [](const OrthoParameters& p) {
    try {
      ortho_camera(p);
    } catch (const CameraError& e) {
      EXPECT_NE(std::string(e.what()).find("to ortho()"), std::string::npos) << e.what();
      return e.parameter;
    }
    return std::string("(none)");
  };
  const Point3 e{0, -10, 0}, t{0, 0, 0};
  EXPECT_EQ(parameter_of({.eye = e, .target = e}), "target");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .up = {0, 1, 0}}), "up");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .height = 0}), "height");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .height = -2}), "height");
  EXPECT_EQ(parameter_of({.eye = e, .target = t, .aspect = -1}), "aspect");
  EXPECT_EQ(parameter_of({.eye = e, .target = t}), "(none)");
}

}  // namespace
}  // namespace hlr
