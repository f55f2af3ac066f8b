// Evaluates and renders the selected frames of a program, several at a time if asked. Frames are
// independent, each evaluation builds its own scene, and results are collected in frame order, so the
// output does not depend on the number of jobs. When frames fail, the failure of the lowest frame is
// reported, again whatever the number of jobs.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/hlr/visible_segment.hpp"
#include "lang/diagnostic.hpp"
#include "runtime/frame_scene.hpp"
#include "runtime/program.hpp"

namespace hlr::runtime {

// A failure that is not at a place in the script: no camera declared, an unknown --camera name.
struct RunError : std::runtime_error {
  RunError(const std::string& message, std::string hint_, int exit_code_)
      : std::runtime_error(message), hint(std::move(hint_)), exit_code(exit_code_) {}
  std::string hint;
  int exit_code;
};

struct RunOptions {
  std::optional<std::string> camera;  // --camera NAME; else the last camera declared
  std::optional<bool> hidden;         // --hidden; else the script's style, else off
  unsigned jobs = 1;                  // frames in flight
  bool render = true;                 // false: evaluate and pick cameras only (hlrscript check)
};

struct FrameOutput {
  FrameTime time;
  std::string camera_name;
  Camera camera;
  std::vector<std::string> object_names;  // by VisibleSegment::object
  std::size_t faces = 0;                  // faces drawn
  std::vector<VisibleSegment> segments;
  bool hidden = false;  // the segments include hidden pieces
  FrameStats stats;
  std::optional<OutputSetting> output;  // the script's output name for this frame
  std::optional<PaperSetting> paper;
  std::vector<int> object_pens;  // by object: draw ... pen N
  std::optional<int> hidden_pen;  // style hidden dashed pen N
  std::vector<PenSetting> pens;
  std::vector<PlotterSetting> plotters;
  double evaluate_seconds = 0;
  double render_seconds = 0;
};

struct RunResult {
  std::vector<FrameOutput> frames;         // in the order of `frames` given to run_frames
  std::vector<lang::Diagnostic> warnings;  // from every frame, each distinct one once
};

// The camera a frame is drawn with: `wanted` if given, else the last declared. Throws RunError.
const NamedCamera& choose_camera(const FrameScene& scene, const std::optional<std::string>& wanted,
                                 const std::string& script_name);

// Evaluates (and renders) `frames`. `first` is frame 0's scene when the caller has already evaluated it;
// `frame_count` and `fps` come from its animate statement. Throws EvalError or RunError of the lowest
// failing frame; for an animation, the message of an EvalError names the frame.
RunResult run_frames(const Program& program, const std::vector<int>& frames, int frame_count, double fps,
                     const RunOptions& options, std::optional<FrameScene> first = std::nullopt);

}  // namespace hlr::runtime
