// Where the frames go. The name comes from -o (where {frame} and {frame:FMT} are replaced by the frame
// number), else from the script's `output` statement (evaluated per frame), else FILE.pdf in the working
// directory. Frames whose names are equal share one file (PDF pages, JSON frames) in frame order; a
// name that differs per frame gives one file per frame. The extension picks the device; SVG, PNG and
// HPGL hold one frame per file, so several frames sharing such a name is an error that asks for
// {frame:03} in the name. runtime/pipeline/frame_pipeline.cpp writes them.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/device/formats/json_device.hpp"
#include "core/device/page/device.hpp"
#include "core/plan/pen_plan.hpp"
#include "runtime/eval/frame_scene.hpp"
#include "runtime/eval/program.hpp"
#include "runtime/pipeline/run_error.hpp"

namespace hlr::runtime {

struct OutputTarget {
  std::filesystem::path path;
  DeviceKind device = DeviceKind::Pdf;
  std::vector<std::size_t> frames;       // indices into the frames given to plan_outputs, in order
  std::optional<lang::SourceSpan> span;  // the script's `output` name, when the path comes from it
};

struct FrameName {
  int frame = 0;
  std::optional<OutputSetting> script_output;
};

// True when an -o pattern has a {frame...} field.
bool has_frame_field(const std::string& pattern);
// The -o pattern with {frame} / {frame:FMT} replaced; throws RunError (exit 64) for any other {...}.
std::string substitute_frame(const std::string& pattern, int frame);

// The file one frame goes to (frames = {index}). Throws as plan_outputs() does.
OutputTarget target_for_frame(const std::optional<std::string>& cli_pattern, const FrameName& frame,
                              std::size_t index, const Program& program);

// The error for two frames sent to a file that holds one frame: at the script's output statement when
// the name came from there (EvalError), else RunError 64.
[[noreturn]] void fail_several_frames(const OutputTarget& target, int frame_a, int frame_b, bool from_cli);

// Groups frames by file. A bad -o (unknown extension, the input script itself) throws RunError with exit
// 64; the same mistake in the script's output statement throws EvalError at its span.
std::vector<OutputTarget> plan_outputs(const std::optional<std::string>& cli_pattern,
                                       const std::vector<FrameName>& frames, const Program& program);

// Device settings from the command line; each overrides the script's setting when given.
struct DeviceOptions {
  std::optional<std::string> paper;          // --paper A3 | 420x297
  std::optional<bool> landscape;             // --landscape / --portrait
  std::optional<double> margin_mm;           // --margin
  std::optional<double> mm_per_unit;         // --scale: 1 picture unit = N mm instead of fit-to-page
  std::optional<PageFit> fit;                // --fit camera|drawing: what sets the page scale
  // --dash DASH,GAP: hidden lines on plotters as pen-down dashes; --dash solid (unset): whole strokes.
  std::optional<DashPattern> dash = DashPattern{};
  double dpi = 150;                          // --dpi (PNG)
  bool decorations = true;                   // --plain: no frame border or caption
  double step_mm = 0.1;                      // --step: the incremental plotter's step (.steps)
  std::optional<double> line_width_mm;       // --line-width: every pen's width (cairo devices)
  std::optional<std::string> plotter;        // --plotter NAME (HPGL or G-code profile)
  bool clip = false;                         // --clip: cut HPGL at the reach, G-code, plotter SVG at the page
  std::optional<bool> text_strokes;          // --text stroke|outline (default: stroke on plotters)
  std::optional<bool> plotter_svg;           // --svg plotter|document (default: plotter when one is named)
  std::optional<bool> relative;              // --hpgl-moves relative|absolute
  PenOrder pen_order = PenOrder::Optimized;  // --pen-order
  JsonParts json_parts;                      // --json: what each JSON frame holds
  std::size_t plan_effort = kDefaultPlanEffort;  // --plan-effort (work per stroke, Optimized only)
  std::string creation_date;                 // PDF metadata: SOURCE_DATE_EPOCH when set, else now
};

// Throws DeviceError when the target's directory does not exist: checked before any frame is rendered.
void check_writable(const OutputTarget& target);

}  // namespace hlr::runtime
