// The hidden-line engine: scene + camera in, the exact visible pieces of the drawn edges out.
//   edges → cull (back faces of closed solids) → near clip → project → spatial index →
//   hidden intervals (edge behind a face's plane ∩ inside its projected polygon) → visible pieces →
//   picture-frame clip.
// Visibility changes only at computed crossing points; nothing is sampled.
#pragma once

#include <atomic>
#include <chrono>
#include <stdexcept>

#include "core/camera/camera.hpp"
#include "core/hlr/scene.hpp"
#include "core/hlr/visible_segment.hpp"

namespace hlr {

struct HlrOptions {
  bool include_hidden = false;  // also return hidden pieces (hidden = true), for a dashed layer
  // Occlusion levels: when > 0, every point is given the number of surfaces in front of it (every face
  // that separates it from the eye, back faces included, so nothing is culled) and the hidden pieces of
  // levels 1 … max_level are returned (VisibleSegment::level), whatever include_hidden says. The visible
  // pieces are those of max_level 0.
  unsigned max_level = 0;
  bool intersection_lines = true;  // draw where faces cross (of two solids, or of one solid)
  // A visible piece that earlier pieces on the same line already draw (solids sharing an edge line) is
  // left out (core/hlr/coincident_pieces.hpp).
  bool coincident_once = true;
  unsigned threads = 0;  // 0: the caller's task arena (every core unless --jobs bounds it); 1: this thread
  // Checked between chunks of work (a fraction of a millisecond each): when it becomes true the
  // frame stops with RenderCancelled (the REPL's Ctrl-C).
  const std::atomic<bool>* cancel = nullptr;
  // Checked at the same places: past it, the frame stops with FrameTimedOut (--frame-timeout).
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
};

// The work ran past HlrOptions::deadline; nothing of it is kept.
class FrameTimedOut : public std::runtime_error {
 public:
  FrameTimedOut() : std::runtime_error("out of time") {}
};

// The work was stopped through a cancel flag; nothing of it is kept.
class RenderCancelled : public std::runtime_error {
 public:
  RenderCancelled() : std::runtime_error("stopped") {}
};

FrameResult render_frame(const Scene& scene, const Camera& camera, const HlrOptions& options = {});

}  // namespace hlr
