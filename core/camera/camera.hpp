// The camera contract of the engine. Every camera kind (lookat, ortho, Albers' orbit, Desens' 12
// degrees of freedom) reduces to this one description, built by its own constructor file:
//   view = viewFromWorld(world point)              view coordinates (right, up, depth)
//   perspective:  picture = focal · (right, up) / depth + offset    eye at the view origin
//   orthographic: picture = focal · (right, up) + offset           eye at depth −∞
// Depth grows away from the eye. Points with depth below `near_depth` are clipped (perspective only).
// `picture` coordinates are the camera's own (Desens: normalised Y′, Z′; orbit: D·Xe/Ze, D·Ye/Ze).
#pragma once

#include <optional>
#include <string>

#include "core/geometry/affine3.hpp"
#include "core/geometry/rect2.hpp"
#include "core/geometry/vector.hpp"
#include "core/tolerance.hpp"

namespace hlr {

enum class Projection { Perspective, Orthographic };

struct Camera {
  std::string kind = "lookat";  // the constructor that made it: lookat, ortho, orbit, desens
  Projection projection = Projection::Perspective;
  Affine3 viewFromWorld;  // world → (right, up, depth); may be mirror-handed (Albers' eye system)
  double focal = 1;       // picture units per (right/depth) or, orthographic, per world unit
  Vector2 offset{};       // added after projection
  // Perspective near plane, in view depth units (> 0).
  double near_depth = Tolerance::kDefaultNearDepth;
  std::optional<Rect2> frame;  // picture frame: drawn pieces are clipped to it (Desens' WINDOW, aspect:)
  // Without a frame of its own the camera frames the page it is drawn on (core/device/page/page_layout.hpp,
  // picture_frame): the picture spans ±window_half along the drawing area's shorter side. 1 for lookat
  // (the fov) and ortho (the height); 90 for orbit (Albers' drawing window, 180 rows of the CGA screen).
  double window_half = 1;
  // Perspective: the depth of the point looked at (lookat's target), where a view on a sheet takes its
  // scale (core/device/page/sheet_layout.hpp); 0 when the camera does not know one.
  double target_depth = 0;

  // World-space eye position (perspective) and unit viewing direction (both projections).
  Point3 eye_world() const;
  Vector3 direction_world() const;

  Point3 view(Point3 world) const { return viewFromWorld.apply(world); }
  // Picture coordinates of a view-space point; perspective requires depth > 0.
  Point2 project_view(Point3 v) const {
    if (projection == Projection::Perspective)
      return {focal * v.x / v.z + offset.x, focal * v.y / v.z + offset.y};
    return {focal * v.x + offset.x, focal * v.y + offset.y};
  }
  Point2 project(Point3 world) const { return project_view(view(world)); }
};

}  // namespace hlr
