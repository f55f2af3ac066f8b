#include "core/camera/orbit_camera.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "core/camera/camera_error.hpp"

namespace hlr {
namespace {

// Albers' TETRA with the digest's centred reconstruction of the lost x column (000_albers.md §4.1).
const std::array<Point3, 4> kTetra{Point3{5.773502692, 10, 0}, Point3{5.773502692, -10, 0},
                                   Point3{-11.547005384, 0, 0}, Point3{0, 0, 16.329931620}};

struct Screen {
  double x, y;
};

// Albers' device mapping undone: screen.x = 155 + D·Xe/Ze, screen.y = 89 − 0.93·D·Ye/Ze.
Point2 picture_of(Screen s) { return {s.x - 155, (89 - s.y) / 0.93}; }

void expect_screens(const Camera& c, const std::array<Screen, 4>& screens) {
  for (int i = 0; i < 4; ++i) {
    SCOPED_TRACE("vertex " + std::to_string(i + 1));
    const Point2 want = picture_of(screens[i]);
    const Point2 got = c.project(kTetra[i]);
    // The digest prints 3 decimals of screen units.
    EXPECT_NEAR(got.x, want.x, 6e-4);
    EXPECT_NEAR(got.y, want.y, 6e-4 / 0.93);
  }
}

// Albers' back-face test: W·N with W from the face's first vertex to the eye.
double facing(const Camera& c, int a, int b, int d) {
  const Point3 v1 = kTetra[a - 1], v2 = kTetra[b - 1], v3 = kTetra[d - 1];
  return dot(c.eye_world() - v1, cross(v2 - v1, v3 - v1));
}

TEST(OrbitCamera, AlbersView1EyeCoordinatesAndScreen) {
  const Camera c = orbit_camera({.theta_deg = 0, .phi_deg = 90, .rho = 425, .d = 1549});
  EXPECT_EQ(c.kind, "orbit");
  EXPECT_EQ(c.projection, Projection::Perspective);
  EXPECT_DOUBLE_EQ(c.focal, 1549);
  EXPECT_FALSE(c.frame.has_value());
  EXPECT_DOUBLE_EQ(c.near_depth, 425e-6);
  const std::array<Point3, 4> eye_coordinates{Point3{10, 0, 419.2265}, Point3{-10, 0, 419.2265},
                                              Point3{0, 0, 436.5470}, Point3{0, 16.3299, 425}};
  for (int i = 0; i < 4; ++i) {
    const Point3 v = c.view(kTetra[i]);
    EXPECT_NEAR(v.x, eye_coordinates[i].x, 1e-4);
    EXPECT_NEAR(v.y, eye_coordinates[i].y, 1e-4);
    EXPECT_NEAR(v.z, eye_coordinates[i].z, 1e-4);
  }
  expect_screens(c, {Screen{191.949, 89.000}, {118.051, 89.000}, {155.000, 89.000}, {155.000, 33.648}});
  EXPECT_NEAR(facing(c, 1, 4, 2), 136918.8, 0.1);
}

TEST(OrbitCamera, AlbersView2Screen) {
  const Camera c = orbit_camera({.theta_deg = 45, .phi_deg = 90, .rho = 425, .d = 1549});
  expect_screens(c, {Screen{166.186, 89}, {114.632, 89}, {184.198, 89}, {155.000, 33.648}});
  EXPECT_GT(facing(c, 1, 4, 2), 0);
  EXPECT_GT(facing(c, 1, 3, 4), 0);
  EXPECT_LT(facing(c, 3, 2, 4), 0);
}

TEST(OrbitCamera, AlbersView3ScreenAndFacing) {
  const Camera c = orbit_camera({.theta_deg = 45, .phi_deg = 60, .rho = 425, .d = 1549});
  expect_screens(c, {Screen{166.146, 108.343}, {114.595, 83.966}, {184.272, 75.389}, {155.000, 40.125}});
  EXPECT_NEAR(facing(c, 1, 4, 2), 107651.8, 0.1);
  EXPECT_NEAR(facing(c, 1, 3, 4), 53763.9, 0.1);
  EXPECT_LT(facing(c, 3, 2, 4), 0);
  EXPECT_LT(facing(c, 1, 2, 3), 0);
}

TEST(OrbitCamera, EyeOnSphereLookingAtOrigin) {
  const OrbitParameters p{.theta_deg = 30, .phi_deg = 70, .rho = 200, .d = 10};
  const Camera c = orbit_camera(p);
  const double t = 30 * std::numbers::pi / 180, f = 70 * std::numbers::pi / 180;
  const Point3 eye = c.eye_world();
  EXPECT_NEAR(eye.x, 200 * std::sin(f) * std::cos(t), 1e-12);
  EXPECT_NEAR(eye.y, 200 * std::sin(f) * std::sin(t), 1e-12);
  EXPECT_NEAR(eye.z, 200 * std::cos(f), 1e-12);
  const Vector3 d = c.direction_world();
  EXPECT_NEAR(d.x, -eye.x / 200, 1e-12);
  EXPECT_NEAR(d.y, -eye.y / 200, 1e-12);
  EXPECT_NEAR(d.z, -eye.z / 200, 1e-12);
  const Point3 origin = c.view({0, 0, 0});
  EXPECT_NEAR(origin.x, 0, 1e-12);
  EXPECT_NEAR(origin.y, 0, 1e-12);
  EXPECT_NEAR(origin.z, 200, 1e-12);
  // +Z projects upward for φ < 180°.
  EXPECT_GT(c.project({0, 0, 10}).y, 0);
}

TEST(OrbitCamera, RejectsBadParameters) {
  const auto parameter_of = [](const OrbitParameters& p) {
    try {
      orbit_camera(p);
    } catch (const CameraError& e) {
      return e.parameter;
    }
    return std::string("(none)");
  };
  EXPECT_EQ(parameter_of({.rho = 0}), "rho");
  EXPECT_EQ(parameter_of({.rho = -5}), "rho");
  EXPECT_EQ(parameter_of({.d = 0}), "d");
  EXPECT_EQ(parameter_of({.d = INFINITY}), "d");
  EXPECT_EQ(parameter_of({.theta_deg = NAN}), "theta");
  EXPECT_EQ(parameter_of({.phi_deg = INFINITY}), "phi");
  EXPECT_EQ(parameter_of({}), "(none)");
  try {
    orbit_camera({.rho = -5});
    FAIL();
  } catch (const CameraError& e) {
    EXPECT_STREQ(e.what(), "bad argument 'rho' to orbit(): must be a positive distance (got -5)");
  }
}

}  // namespace
}  // namespace hlr
