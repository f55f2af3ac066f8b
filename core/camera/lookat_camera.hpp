// The general perspective camera: an eye looking at a target, with an up hint that sets the roll.
// View axes are right = normalize(forward × up), true up = right × forward, depth along forward; a
// right-handed world therefore shows +right to the right and +up upward on the picture.
#pragma once

#include <optional>

#include "core/camera/camera.hpp"
#include "core/geometry/affine3.hpp"
#include "core/geometry/vector.hpp"

namespace hlr {

struct LookatParameters {
  Point3 eye;
  Point3 target;
  Vector3 up{0, 0, 1};
  double fov_deg = 40;  // the field of view across the picture's [−1, 1]: the page's shorter side, or
                        // the frame's height with an aspect
  double aspect = 0;    // > 0: frame [−aspect, aspect] × [−1, 1]; 0: the page's (page_layout.hpp)
  double near = 0;      // near-plane depth; 0: Tolerance::kLookatNearFraction·|target − eye|
};

// focal = 1/tan(fov/2). Throws CameraError naming the parameter: eye == target, up zero or parallel to the
// viewing direction, fov outside (0, 180), negative aspect or near, any value not finite.
Camera lookat_camera(const LookatParameters& p);

namespace detail {
// Shared with ortho(): world → (right, up, forward) with the eye at the origin; errors name `function`.
Affine3 look_at_view_from_world(Point3 eye, Point3 target, Vector3 up, const char* function);
// Frame [−aspect, aspect] × [−1, 1] for aspect > 0, none for 0; negative or non-finite is an error.
std::optional<Rect2> aspect_frame(double aspect, const char* function);
}  // namespace detail

}  // namespace hlr
