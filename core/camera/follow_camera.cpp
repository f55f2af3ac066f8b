#include "core/camera/follow_camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/camera/camera_error.hpp"
#include "core/camera/lookat_camera.hpp"
#include "core/tolerance.hpp"

namespace hlr {

namespace {

// The signed rate at which the heading (the tangent seen along `up`) turns, radians per unit of t;
// positive counter-clockwise seen from above (a left turn).
double turn_rate(const FollowParameters& p, double u) {
  const double h = Tolerance::kPathTangentStep / static_cast<double>(p.path.size() - 1);
  const double lo = std::max(0.0, u - h), hi = std::min(1.0, u + h);
  const Vector3 a = path_tangent(p.path, p.curve, lo), b = path_tangent(p.path, p.curve, hi);
  const Vector3 up = normalize(p.up);
  const Vector3 fa = a - up * dot(a, up), fb = b - up * dot(b, up);  // flattened headings
  if (length(fa) <= Tolerance::kFloor || length(fb) <= Tolerance::kFloor) return 0;
  const double angle = std::atan2(dot(cross(fa, fb), up), dot(fa, fb));
  return angle / (hi - lo);
}

}  // namespace

Camera follow_camera(const FollowParameters& p) {
  if (p.path.size() < 2) throw CameraError("follow", "path", "needs at least two points");
  for (const Point3& q : p.path)
    if (!is_finite(q)) throw CameraError("follow", "path", "must be finite");
  if (!std::isfinite(p.t)) throw CameraError("follow", "t", "must be finite");
  if (!std::isfinite(p.bank_deg)) throw CameraError("follow", "bank", "must be finite");
  if (length(p.up) == 0 || !is_finite(to_point(p.up)))
    throw CameraError("follow", "up", "must be a finite, non-zero vector");

  const double u = std::clamp(p.t, 0.0, 1.0);
  const Point3 eye = to_point(path_point(p.path, p.curve, u));
  const Vector3 forward = path_tangent(p.path, p.curve, u);
  if (!(length(forward) > Tolerance::kRelative))
    throw CameraError("follow", "path", "does not move at t = " + format_for_message(p.t));

  Vector3 up = normalize(p.up);
  if (p.bank_deg != 0) {
    double sharpest = 0;
    for (int k = 0; k <= kFollowTurnSamples; ++k)
      sharpest = std::max(sharpest, std::abs(turn_rate(p, static_cast<double>(k) / kFollowTurnSamples)));
    if (sharpest > 0) {
      const double roll = p.bank_deg * std::numbers::pi / 180 * turn_rate(p, u) / sharpest;
      // Turning left (positive rate), the up vector leans left: towards the inside of the turn.
      const Vector3 f = normalize(forward);
      const Vector3 left = cross(up, f);
      if (length(left) > Tolerance::kRelative) up = up * std::cos(roll) + normalize(left) * std::sin(roll);
    }
  }
  LookatParameters look;
  look.eye = eye;
  look.target = eye + normalize(forward);
  look.up = up;
  look.fov_deg = p.fov_deg;
  look.aspect = p.aspect;
  try {
    Camera c = lookat_camera(look);
    c.kind = "follow";
    return c;
  } catch (const CameraError& e) {
    throw CameraError("follow", e.parameter == "target" ? "path" : e.parameter,
                      std::string(e.what()).substr(std::string(e.what()).find("): ") + 3));
  }
}

}  // namespace hlr
