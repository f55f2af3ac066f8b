#include "core/camera/desens_camera.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "core/camera/camera_error.hpp"

namespace hlr {

namespace {

// 3x3 matrices in the thesis's row-vector convention: p' = p·M.
using RowMatrix = std::array<std::array<double, 3>, 3>;

double radians(double degrees, bool thesis_pi) {
  // The 1969 program's TPI = 3.1416/180 differs from π/180 by 2.3e-6 relative; the printed digits need it.
  return degrees * (thesis_pi ? 3.1416 / 180.0 : std::numbers::pi / 180.0);
}

// Euler matrix (ROTATN): yaw a about w, then pitch b about the rotated v, then roll c about the rotated u.
RowMatrix rotatn(double a, double b, double c) {
  const double sa = std::sin(a), ca = std::cos(a), sb = std::sin(b), cb = std::cos(b), sc = std::sin(c),
               cc = std::cos(c);
  return {{{cb * ca, cb * sa, -sb},
           {sc * sb * ca - cc * sa, sc * sb * sa + cc * ca, sc * cb},
           {cc * sb * ca + sc * sa, cc * sb * sa - sc * ca, cb * cc}}};
}

// Fixed-axes matrix (FXRTAT) = Rz(a)·Ry(b)·Rx(c) in row form; FXRTAT(−a,−b,−c) is ROTATN(a,b,c)ᵀ.
RowMatrix fxrtat(double a, double b, double c) {
  const double sa = std::sin(a), ca = std::cos(a), sb = std::sin(b), cb = std::cos(b), sc = std::sin(c),
               cc = std::cos(c);
  return {{{ca * cb, sa * cc + sc * ca * sb, sa * sc - cc * ca * sb},
           {-cb * sa, cc * ca - sc * sb * sa, sc * ca + cc * sb * sa},
           {sb, -sc * cb, cc * cb}}};
}

RowMatrix multiply(const RowMatrix& a, const RowMatrix& b) {
  RowMatrix r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  return r;
}

Vector3 row_times(Vector3 p, const RowMatrix& m) {
  return {p.x * m[0][0] + p.y * m[1][0] + p.z * m[2][0], p.x * m[0][1] + p.y * m[1][1] + p.z * m[2][1],
          p.x * m[0][2] + p.y * m[1][2] + p.z * m[2][2]};
}

bool finite(Vector3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void validate(const DesensParameters& p) {
  const auto require_finite = [](bool ok, const char* name) {
    if (!ok) throw CameraError("desens", name, "must be finite");
  };
  require_finite(is_finite(p.object_position), "object_position");
  require_finite(finite(p.attitude), "attitude");
  require_finite(is_finite(p.observer_position), "observer_position");
  require_finite(finite(p.heading), "heading");
  require_finite(std::isfinite(p.offset.x) && std::isfinite(p.offset.y), "offset");
  if (!(std::isfinite(p.focal) && p.focal > 0))
    throw CameraError("desens", "focal", "must be a positive distance " + CameraError::got(p.focal));
  if (!(std::isfinite(p.scale) && p.scale > 0))
    throw CameraError("desens", "scale", "must be positive " + CameraError::got(p.scale));
}

}  // namespace

Camera desens_camera(const DesensParameters& p) {
  validate(p);
  const bool tp = p.thesis_pi;
  // VMVMAT's H0: [ROTATN(α,β,γ); OBJMV − VIEWMV]·FXRTAT(−ψ,−θ,−φ).
  const RowMatrix object =
      rotatn(radians(p.attitude.x, tp), radians(p.attitude.y, tp), radians(p.attitude.z, tp));
  const RowMatrix observer =
      fxrtat(-radians(p.heading.x, tp), -radians(p.heading.y, tp), -radians(p.heading.z, tp));
  const RowMatrix m = multiply(object, observer);
  const Vector3 t = row_times(p.object_position - p.observer_position, observer);

  // Column j of the row matrix gives viewing-plane coordinate j; reorder to (y, z, F − x).
  Camera c;
  c.kind = "desens";
  c.projection = Projection::Perspective;
  c.viewFromWorld = Affine3::from_rows({m[0][1], m[1][1], m[2][1]}, {m[0][2], m[1][2], m[2][2]},
                                       {-m[0][0], -m[1][0], -m[2][0]}, {t.y, t.z, p.focal - t.x});
  c.focal = p.focal / p.scale;
  c.offset = {p.offset.x / p.scale, p.offset.y / p.scale};
  c.near_depth = p.focal;  // picture plane x = 0 lies F in front of the eye
  c.frame = Rect2{-1, -1, 1, 1};
  return c;
}

DesensObserverPoints desens_observer_points(const DesensParameters& p) {
  // The affine inverse of the whole map inverts the object rotation correctly (by its transpose).
  const Affine3 world_from_view = desens_camera(p).viewFromWorld.inverse();
  const double f = p.focal;
  // Viewing-plane (x, y, z) is view (y, z, F − x).
  const auto plane = [&](double x, double y, double z) { return world_from_view.apply(Point3{y, z, f - x}); };
  return {plane(0, 0, 0), plane(0, 1, 0), plane(0, 0, 1), plane(f, 0, 0)};
}

}  // namespace hlr
