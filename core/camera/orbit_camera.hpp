// Albers' orbit camera (reference/000_albers.md §2): the eye sits on a sphere of radius ρ about the world
// origin, at azimuth θ and polar angle φ, and always looks at the origin with no roll.
//   eye = (ρ sinφ cosθ, ρ sinφ sinθ, ρ cosφ)
//   Xe = −x sinθ + y cosθ
//   Ye = −x cosθ cosφ − y sinθ cosφ + z sinφ
//   Ze = −x cosθ sinφ − y sinθ sinφ − z cosφ + ρ
//   picture = (D·Xe/Ze, D·Ye/Ze)        (Albers' screen adds CenterX and flips/scales y per device)
#pragma once

#include "core/camera/camera.hpp"

namespace hlr {

struct OrbitParameters {
  double theta_deg = 45;  // azimuth from the XZ plane (HLR02/03 default π/4)
  double phi_deg = 90;    // polar angle from +Z
  double rho = 425;       // eye distance from the origin
  double d = 1549;        // screen distance: image scale without changing perspective
};

// Camera with (right, up, depth) = (Xe, Ye, Ze), focal = D, no frame. The near plane lies at
// Tolerance::kOrbitNearFraction·ρ: Albers never clips at the eye, so it only keeps the division defined, as
// close to the eye as is safe. Throws CameraError when rho or d is not positive or any value is not finite.
Camera orbit_camera(const OrbitParameters& p);

}  // namespace hlr
