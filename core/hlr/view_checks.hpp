// Views that draw nonsense though nothing is wrong with the scene or the camera alone: the eye inside a
// closed solid (the picture shows the solid's inside, every face of it hiding the rest), or a near plane
// that cuts away most of what lies in front of the eye. The pipeline warns about both (runtime/
// frame_pipeline.cpp); the engine draws such views as exactly as any other.
#pragma once

#include <cstddef>
#include <optional>

#include "core/camera/camera.hpp"
#include "core/hlr/scene.hpp"

namespace hlr {

struct ViewProblems {
  std::optional<std::size_t>
      eye_inside;                     // the first closed object (index into Scene::objects) around the eye
  std::size_t vertices_in_front = 0;  // perspective: vertices at depth > 0
  std::size_t vertices_cut_away = 0;  // of those, the ones nearer than the near plane
  // Most of what lies in front of the eye is nearer than the near plane.
  bool near_plane_cuts_most() const {
    return vertices_cut_away > 0 && 2 * vertices_cut_away > vertices_in_front;
  }
};

ViewProblems check_view(const Scene& scene, const Camera& camera);

// Whether `p` lies inside the closed solid (parity of the faces a ray from p crosses; a ray that grazes an
// edge or a vertex is cast again in another direction). False for an open solid and for points on its
// surface within the coincidence tolerance.
bool point_inside_closed_solid(const Solid& solid, Point3 p);

}  // namespace hlr
