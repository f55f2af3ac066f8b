#include "core/camera/camera_adjust.hpp"

#include <cmath>
#include <numbers>

#include "core/camera/camera_error.hpp"

namespace hlr {

Camera adjusted_camera(const Camera& camera, const CameraAdjustment& a) {
  auto finite = [](const char* name, double v) {
    if (!std::isfinite(v)) throw CameraError("adjust", name, "must be finite");
  };
  finite("theta", a.theta_deg);
  finite("phi", a.phi_deg);
  finite("dolly", a.dolly);
  if (!(std::isfinite(a.zoom) && a.zoom > 0))
    throw CameraError("adjust", "zoom", "must be finite and positive");
  if (!(std::isfinite(a.pivot.x) && std::isfinite(a.pivot.y) && std::isfinite(a.pivot.z)))
    throw CameraError("adjust", "pivot", "must be finite");
  constexpr double kRad = std::numbers::pi / 180;
  Camera out = camera;
  // The camera moves by R = Rz(θ)·Rright(−φ) about the pivot; the world moves by R⁻¹ before the view.
  const Vector3 right = normalize(camera.viewFromWorld.row(0));
  const Vector3 p = to_vector(a.pivot);
  const Affine3 world_motion = Affine3::translation(-1.0 * p)
                                   .then(Affine3::rotation({0, 0, 1}, -a.theta_deg * kRad))
                                   .then(Affine3::rotation(right, a.phi_deg * kRad))
                                   .then(Affine3::translation(p));
  out.viewFromWorld = world_motion.then(camera.viewFromWorld).then(Affine3::translation({0, 0, -a.dolly}));
  out.focal = camera.focal * a.zoom;
  return out;
}

}  // namespace hlr
