// Everything that decides how one frame is drawn, resolved once from the frame's scene and the command
// line: the camera, the hidden layer, the file, its device, the page and the pen plan's settings. Every
// later stage of the pipeline (runtime/pipeline/frame_pipeline.cpp) reads this value and nothing else.
// Precedence: the command line, then the script's statement for this frame, then the defaults.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/device/page/device.hpp"
#include "core/device/page/page_plot.hpp"
#include "runtime/eval/frame_scene.hpp"
#include "runtime/pipeline/output_plan.hpp"

namespace hlr::runtime {

// What the command line decides for every frame of a run.
struct RunSettings {
  std::string title;                  // the script's name: captions, PDF and JSON metadata
  int frame_count = 1;                // of the animation, for captions
  std::optional<std::string> camera;  // --camera NAME; else the last camera declared
  std::optional<HiddenStyle> hidden;  // --hidden or --levels; else the script's style, else off
  std::optional<std::string> output;  // -o pattern
  DeviceOptions device;               // --paper, --plotter, --dpi, ...
};

struct FrameSettings {
  const NamedCamera* camera = nullptr;  // into the frame's scene (a sheet: its first view's), or own_camera
  // A mesh file's frame from a script with no camera: it draws nothing, so any camera serves the frame.
  std::shared_ptr<const NamedCamera> own_camera;
  bool sheet = false;                   // the frame's views on one sheet (runtime/pipeline/sheet_render.hpp)
  // The camera with its picture frame on this page (core/device/page/page_layout.hpp framed_camera): what the
  // engine clips to and the devices lay out. Set by resolve_device().
  Camera camera_on_page;
  HiddenStyle hidden;  // whether (and by which levels) hidden pieces are computed, planned and drawn
  OutputTarget target;
  std::shared_ptr<const Device> device;
  PagePlotOptions plot;  // page (margin widened to the device's reach), pens by object, plan settings
  std::string caption;
};

// The page: the frame's paper setting, with the command line's paper, orientation, margin, scale and fit
// taking precedence.
PageSpec page_spec_for(const FrameScene& scene, const DeviceOptions& d);

// The camera a frame is drawn with: `wanted` (a camera's or a view's name) if given, else the first view
// when there are views (the sheet), else the last camera declared. Throws RunError.
const NamedCamera& choose_camera(const FrameScene& scene, const std::optional<std::string>& wanted,
                                 const std::string& script_name);

// Resolves the camera and the file only (hlrscript check, and the checks made before any rendering).
// Throws RunError, or EvalError at the script's statement.
FrameSettings resolve_target(const FrameScene& scene, std::size_t index, const RunSettings& run,
                             const Program& program);

// Completes `settings` (from resolve_target) with the device, page and plan. Throws DeviceError (a page
// the plotter does not take), RunError or EvalError (an unknown plotter).
void resolve_device(const FrameScene& scene, const RunSettings& run, FrameSettings& settings);

}  // namespace hlr::runtime
