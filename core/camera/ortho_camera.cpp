#include "core/camera/ortho_camera.hpp"

#include <cmath>

#include "core/camera/camera_error.hpp"
#include "core/camera/lookat_camera.hpp"

namespace hlr {

Camera ortho_camera(const OrthoParameters& p) {
  Camera c;
  c.kind = "ortho";
  c.projection = Projection::Orthographic;
  c.viewFromWorld = detail::look_at_view_from_world(p.eye, p.target, p.up, "ortho");
  if (!(std::isfinite(p.height) && p.height > 0))
    throw CameraError("ortho", "height", "must be a positive length " + CameraError::got(p.height));
  c.frame = detail::aspect_frame(p.aspect, "ortho");
  c.focal = 2 / p.height;
  c.offset = {};
  return c;
}

}  // namespace hlr
