#include "core/camera/lookat_camera.hpp"

#include <cmath>
#include <numbers>

#include "core/camera/camera_error.hpp"
#include "core/tolerance.hpp"

namespace hlr {

namespace detail {

Affine3 look_at_view_from_world(Point3 eye, Point3 target, Vector3 up, const char* function) {
  if (!is_finite(eye)) throw CameraError(function, "eye", "must be finite");
  if (!is_finite(target)) throw CameraError(function, "target", "must be finite");
  if (!is_finite(to_point(up))) throw CameraError(function, "up", "must be finite");
  if (eye == target) throw CameraError(function, "target", "must differ from the eye position");
  if (length(up) == 0) throw CameraError(function, "up", "must not be the zero vector");

  const Vector3 forward = normalize(target - eye);
  const Vector3 side = cross(forward, normalize(up));
  // |side| is the sine of the angle between up and forward; below the coincidence tolerance the roll is
  // undetermined.
  if (length(side) <= Tolerance::kRelative)
    throw CameraError(function, "up", "parallel to the viewing direction");
  const Vector3 right = normalize(side);
  const Vector3 true_up = cross(right, forward);
  const Vector3 e = to_vector(eye);
  return Affine3::from_rows(right, true_up, forward, {-dot(right, e), -dot(true_up, e), -dot(forward, e)});
}

std::optional<Rect2> aspect_frame(double aspect, const char* function) {
  if (!(std::isfinite(aspect) && aspect >= 0))
    throw CameraError(function, "aspect", "must be positive, or 0 for no frame " + CameraError::got(aspect));
  if (aspect == 0) return std::nullopt;
  return Rect2{-aspect, -1, aspect, 1};
}

}  // namespace detail

Camera lookat_camera(const LookatParameters& p) {
  Camera c;
  c.kind = "lookat";
  c.projection = Projection::Perspective;
  c.viewFromWorld = detail::look_at_view_from_world(p.eye, p.target, p.up, "lookat");
  if (!(std::isfinite(p.fov_deg) && p.fov_deg > 0 && p.fov_deg < 180))
    throw CameraError("lookat", "fov", "must be between 0 and 180 degrees " + CameraError::got(p.fov_deg));
  c.frame = detail::aspect_frame(p.aspect, "lookat");
  if (!(std::isfinite(p.near) && p.near >= 0))
    throw CameraError("lookat", "near",
                      "must be a positive depth, or 0 for the default " + CameraError::got(p.near));
  c.focal = 1 / std::tan(p.fov_deg * std::numbers::pi / 360);
  c.offset = {};
  c.target_depth = distance(p.target, p.eye);
  // Default near plane: close enough never to cut a visible object, far enough to keep 1/depth tame.
  c.near_depth = p.near > 0 ? p.near : Tolerance::kLookatNearFraction * distance(p.target, p.eye);
  return c;
}

}  // namespace hlr
