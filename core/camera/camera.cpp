#include "core/camera/camera.hpp"

namespace hlr {

Point3 Camera::eye_world() const { return viewFromWorld.inverse().apply(Point3{0, 0, 0}); }

Vector3 Camera::direction_world() const {
  return normalize(viewFromWorld.inverse().apply(Vector3{0, 0, 1}));
}

}  // namespace hlr
