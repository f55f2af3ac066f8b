// The orthographic camera: parallel projection along eye → target, with the same axes as lookat().
#pragma once

#include "core/camera/camera.hpp"
#include "core/geometry/vector.hpp"

namespace hlr {

struct OrthoParameters {
  Point3 eye;
  Point3 target;
  Vector3 up{0, 0, 1};
  double height = 2;  // world units mapped to the picture's [−1, 1] (the page's shorter side, or the
                      // frame's height with an aspect)
  double aspect = 0;  // > 0: frame [−aspect, aspect] × [−1, 1]; 0: the page's (page_layout.hpp)
};

// focal = 2/height. Throws CameraError naming the parameter: eye == target, up zero or parallel to the
// viewing direction, height not positive, negative aspect, any value not finite.
Camera ortho_camera(const OrthoParameters& p);

}  // namespace hlr
