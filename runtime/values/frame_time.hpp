// The values bound as `frame`, `t`, `time` and `frames` before an evaluation: where in the sequence a
// frame is. t and time always come from the whole sequence, so a shard or a --frames subset renders
// each frame exactly as the full run does.
#pragma once

namespace hlr::runtime {

inline constexpr double kDefaultFps = 24;  // without `animate ... fps F`

struct FrameTime {
  int frame = 0;
  double t = 0;     // frame / (N − 1), 0 for a single frame
  double time = 0;  // seconds: frame / fps
  int frames = 1;   // N, the sequence's length
};

}  // namespace hlr::runtime
