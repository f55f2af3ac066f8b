#include "core/camera/orbit_camera.hpp"

#include <cmath>
#include <numbers>

#include "core/camera/camera_error.hpp"

namespace hlr {

Camera orbit_camera(const OrbitParameters& p) {
  if (!std::isfinite(p.theta_deg)) throw CameraError("orbit", "theta", "must be finite");
  if (!std::isfinite(p.phi_deg)) throw CameraError("orbit", "phi", "must be finite");
  if (!(std::isfinite(p.rho) && p.rho > 0))
    throw CameraError("orbit", "rho", "must be a positive distance " + CameraError::got(p.rho));
  if (!(std::isfinite(p.d) && p.d > 0))
    throw CameraError("orbit", "d", "must be a positive distance " + CameraError::got(p.d));

  const double theta = p.theta_deg * std::numbers::pi / 180, phi = p.phi_deg * std::numbers::pi / 180;
  const double st = std::sin(theta), ct = std::cos(theta), sp = std::sin(phi), cp = std::cos(phi);
  Camera c;
  c.kind = "orbit";
  c.projection = Projection::Perspective;
  // Albers' product ABCD, transposed into column form; its eye system is left-handed.
  c.viewFromWorld =
      Affine3::from_rows({-st, ct, 0}, {-ct * cp, -st * cp, sp}, {-ct * sp, -st * sp, -cp}, {0, 0, p.rho});
  c.focal = p.d;
  c.offset = {};
  c.near_depth = Tolerance::kOrbitNearFraction * p.rho;
  c.frame.reset();
  // Albers' pictures are in screen units; his drawing window is rows 20–199 of the 320 × 200 CGA screen.
  c.window_half = 90;
  return c;
}

}  // namespace hlr
