// A camera that flies along a path and looks along it, leaning into turns: the eye at the path's point
// at u = t, looking along the path's tangent there, its up vector turned about the view direction by
// bank × (the turn rate here ÷ the sharpest turn rate on the path) degrees — into the turn, as an
// aircraft banks. The turn rate is that of the heading seen along `up` (a climb does not bank).
#pragma once

#include <vector>

#include "core/animation/keyframe_track.hpp"
#include "core/camera/camera.hpp"

namespace hlr {

struct FollowParameters {
  std::vector<Point3> path;  // at least two points, spaced evenly in t
  double t = 0;              // 0 at the first point, 1 at the last
  Vector3 up{0, 0, 1};
  double bank_deg = 0;  // the roll at the sharpest turn; 0: never leans
  double fov_deg = 40;
  double aspect = 0;  // as lookat
  TrackCurve curve = TrackCurve::CatmullRom;
};

// Throws CameraError naming the parameter (function "follow"): fewer than two points, a path that does
// not move at t, up along the path there, fov outside (0, 180), anything not finite.
Camera follow_camera(const FollowParameters& p);

// Samples of the turn rate taken along the path to find its sharpest turn.
inline constexpr int kFollowTurnSamples = 256;

}  // namespace hlr
