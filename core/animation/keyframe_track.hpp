// Keyframe tracks and splines through points. A track is a list of keys (time, value) with times
// increasing; at a time between two keys the value is interpolated — eased (each key's easing shapes
// the stretch that starts at it), or along a cubic spline through all the keys (Catmull-Rom with the
// keys' own spacing, or the natural spline: C², zero curvature at the ends). Before the first key and
// after the last the track holds. Values are vectors; numbers use x.
#pragma once

#include <stdexcept>
#include <vector>

#include "core/animation/easing.hpp"
#include "core/geometry/vector.hpp"

namespace hlr {

struct Keyframe {
  double time = 0;
  Vector3 value;
  Easing ease = Easing::Linear;  // from this key to the next
};

enum class TrackCurve { Eased, CatmullRom, Natural };

// Throws std::invalid_argument "key K: ..." unless there is a key and times strictly increase, all finite.
void check_keys(const std::vector<Keyframe>& keys);

// The track at `at`. The keys must pass check_keys.
Vector3 evaluate_track(const std::vector<Keyframe>& keys, TrackCurve curve, double at);

// A smooth path through `points` (at least one), u from 0 (the first) to 1 (the last), the points
// spaced evenly in u. `curve` Eased means straight lines between them.
Vector3 path_point(const std::vector<Point3>& points, TrackCurve curve, double u);
// The path's direction at u, d point / du (one-sided at the ends); zero for a single point.
Vector3 path_tangent(const std::vector<Point3>& points, TrackCurve curve, double u);

}  // namespace hlr
