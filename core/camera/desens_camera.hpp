// Desens' (1969) camera with twelve degrees of freedom: the object has a position and a yaw–pitch–roll
// attitude, the observer (the viewing plane) has its own position and yaw–pitch–roll heading.
// This reproduces the thesis's VMVMAT/CONV3D transform exactly (reference/001_desens.md §1):
//   viewing-plane (x, y, z) = ([u v w]·ROTATN(α,β,γ) + OBJMV − VIEWMV)·FXRTAT(−ψ,−θ,−φ)   (row vectors)
//   Y′ = (F·y/(F − x) + YOFF)/S,   Z′ = (F·z/(F − x) + ZOFF)/S,   printed depth = x
// The eye is at x = +F and looks toward −x; the picture plane is x = 0. "World" coordinates of the
// resulting Camera are the object coordinates (u, v, w).
#pragma once

#include "core/camera/camera.hpp"
#include "core/geometry/vector.hpp"

namespace hlr {

struct DesensParameters {
  Point3 object_position{-40, 0, 0};  // OBJMV, in reference axes
  Vector3 attitude{};          // object yaw α, pitch β, roll γ in degrees (Euler: α, then β, then γ)
  Point3 observer_position{};  // VIEWMV, in reference axes
  Vector3 heading{};           // observer yaw ψ, pitch θ, roll φ in degrees (θ < 0 looks down)
  double focal = 1.5;          // F: eye to picture plane
  double scale = 0.5;          // S: picture half-width in picture-plane units
  Vector2 offset{};            // YOFF, ZOFF: added to the picture before scaling
  // Convert degrees with TPI = 3.1416/180 as the 1969 program did, so its printed digits reproduce.
  bool thesis_pi = false;
};

// Camera: viewFromWorld maps object (u, v, w) to (right, up, depth) = (y, z, F − x); focal = F/S;
// offset = (YOFF/S, ZOFF/S); near_depth = F (Desens clips at the picture plane x = 0); frame [−1, 1]².
// Throws CameraError naming the parameter when focal or scale is not positive or any value is not finite.
Camera desens_camera(const DesensParameters& p);

// The thesis's OBSPOS: observer points in object coordinates (the hidden-line tests need them there).
struct DesensObserverPoints {
  Point3 picture_origin;  // viewing-plane origin (x = y = z = 0)
  Point3 picture_y1;      // the point y = 1 of the picture plane
  Point3 picture_z1;      // the point z = 1 of the picture plane
  Point3 eye;             // the focal point x = F
};
// Uses the true inverse of the object rotation. The thesis multiplied by ROTATN(−α,−β,−γ), which is the
// inverse only when at most one object angle is non-zero (true of all its examples); for compound
// attitudes the inverse is the transpose, FXRTAT(−α,−β,−γ).
DesensObserverPoints desens_observer_points(const DesensParameters& p);

}  // namespace hlr
