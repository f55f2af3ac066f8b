// The exact test at the heart of the engine: which part of an edge piece does one face hide?
// A point of the edge is hidden by the face when it lies behind the face's plane (seen from the eye)
// and its projection lies strictly inside the face's projected polygon. The first condition holds on one
// interval (the plane is crossed at most once); the second on the intervals between the crossings of
// the projected edge with the polygon's rings. Both are computed, never sampled.
#pragma once

#include <vector>

#include "core/hlr/frame_setup.hpp"
#include "core/hlr/interval_set.hpp"

namespace hlr {

struct OcclusionScratch {
  std::vector<double> breaks;
};

// Adds to `hidden` the parameter intervals (t along candidate.view0 → view1, linear in view space)
// that `occluder` hides.
void add_hidden_intervals(const FrameSetup& setup, const Camera& camera, const Candidate& candidate,
                          const Occluder& occluder, OcclusionScratch& scratch, IntervalSet& hidden);

// Picture parameter s (along pic0 → pic1) of view parameter t, and back. Perspective makes the map a
// Möbius transform, monotonic while both ends are in front of the eye.
double picture_param(const Candidate& c, const Camera& camera, double t);
double view_param(const Candidate& c, const Camera& camera, double s);

}  // namespace hlr
