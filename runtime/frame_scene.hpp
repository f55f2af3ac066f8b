// What one evaluation of a script produces for one frame: the scene to draw, the cameras declared, and
// the settings statements (animate, output, paper, style). Plain data; no language types besides spans.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/device/page_layout.hpp"
#include "core/hlr/scene.hpp"
#include "lang/ast.hpp"
#include "lang/diagnostic.hpp"

namespace hlr::runtime {

// The values bound as `frame`, `t` and `time` before an evaluation.
struct FrameTime {
  int frame = 0;
  double t = 0;     // frame / (N − 1), 0 for a single frame
  double time = 0;  // seconds: frame / fps
};

struct NamedCamera {
  std::string name;
  Camera camera;
  lang::SourceSpan span;  // the `camera` statement
};

struct AnimationSetting {  // animate frames N fps F
  int frames = 1;
  double fps = 24;
  lang::SourceSpan span;
};

struct OutputSetting {        // output "pattern"
  std::string name;           // the pattern evaluated for this frame
  bool interpolated = false;  // the pattern has {...}: each frame may name its own file
  lang::SourceSpan span;      // the pattern string
};

struct PaperSetting {  // paper A4 landscape (or the paper of an output statement)
  std::string size;    // as written
  Paper paper;
  lang::SourceSpan span;
};

struct FrameScene {
  FrameTime time;
  Scene scene;                       // drawn objects in draw order, names unique ("box", "box#2")
  std::vector<NamedCamera> cameras;  // in declaration order
  std::optional<AnimationSetting> animation;
  std::optional<OutputSetting> output;
  std::optional<PaperSetting> paper;
  std::optional<bool> hidden;  // style hidden dashed (true) | off (false)
  std::optional<lang::SourceSpan> hidden_span;
  std::vector<lang::Diagnostic> warnings;
  std::uint64_t steps = 0;
  std::size_t faces_built = 0;
  double evaluate_seconds = 0;
};

}  // namespace hlr::runtime
