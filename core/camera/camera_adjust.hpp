// Albers' function keys, for any camera: step the azimuth θ and the elevation φ about a pivot, move the
// eye along the view (D), and zoom (the focal length, ρ's effect on the picture). A script says the same
// with adjust(camera, theta:, phi:, zoom:, dolly:, pivot:), so the REPL's :orbit, :zoom and :dolly save
// as a camera statement that draws what the session showed.
#pragma once

#include "core/camera/camera.hpp"
#include "core/geometry/vector.hpp"

namespace hlr {

struct CameraAdjustment {
  double theta_deg = 0;  // about the world z axis through the pivot, counter-clockwise seen from above
  double phi_deg = 0;    // about the camera's right axis through the pivot: positive looks from higher up
  double zoom = 1;       // focal length × zoom: 2 shows things twice as large
  double dolly = 0;      // the eye moves this far forward along the view direction
  Point3 pivot{0, 0, 0};
};

// Throws CameraError for a zoom that is not finite and positive, or any value not finite.
Camera adjusted_camera(const Camera& camera, const CameraAdjustment& adjustment);

}  // namespace hlr
