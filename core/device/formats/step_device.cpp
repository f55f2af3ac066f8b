#include "core/device/formats/step_device.hpp"

#include "core/format_number.hpp"
#include "core/limits.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/device/page/atomic_file.hpp"
#include "core/plan/plotter_stepping.hpp"

namespace hlr {
namespace {

constexpr std::size_t kMaxSteps = 200'000'000;  // a 20 km tape at 0.1 mm: far beyond any real drawing
constexpr int kRowsPerLine = 32;

class Tape {
 public:
  void push(char c) {
    if (row_.size() == 2) flush_row();
    row_.push_back(c);
  }
  void pen(char c) {  // 'U', 'D' or 'S', then three "do nothing"
    push(c);
    for (int i = 0; i < 3; ++i) push('0');
  }
  std::string finish() {
    if (!row_.empty()) {
      while (row_.size() < 2) row_.push_back('0');
      flush_row();
    }
    if (rows_in_line_ > 0) text_ += '\n';
    return std::move(text_);
  }

 private:
  void flush_row() {
    if (rows_in_line_ == kRowsPerLine) {
      text_ += '\n';
      rows_in_line_ = 0;
    } else if (rows_in_line_ > 0) {
      text_ += ' ';
    }
    text_ += row_;
    ++rows_in_line_;
    row_.clear();
  }
  std::string text_, row_;
  int rows_in_line_ = 0;
};

}  // namespace

std::string to_plotter_steps(const PlotPage& page, const StepOptions& o, StepCounts* counts_out) {
  if (!(std::isfinite(o.step_mm) && o.step_mm >= kMinPlotterStepMm && o.step_mm <= kMaxPlotterStepMm))
    throw DeviceError("the plotter step must be between " + format_for_message(kMinPlotterStepMm) + " and " +
                      format_for_message(kMaxPlotterStepMm) + " mm");
  if (!(std::isfinite(page.width_mm) && std::isfinite(page.height_mm) && page.width_mm > 0 &&
        page.height_mm > 0))
    throw DeviceError("the page size must be finite and positive");
  const double tol = 0.5 * o.step_mm;
  auto to_grid = [&](Point2 p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw DeviceError("a stroke point is not finite");
    if (p.x < -tol || p.x > page.width_mm + tol || p.y < -tol || p.y > page.height_mm + tol) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "stroke point (%.2f, %.2f) mm is off the %.0f x %.0f mm sheet", p.x, p.y,
                    page.width_mm, page.height_mm);
      throw DeviceError(std::string(buf) + "; use a smaller --scale or leave it to fit the page");
    }
    // Page mm (top-left, y down) → steps from the bottom-left corner, y up.
    return GridPoint{std::llround(p.x / o.step_mm), std::llround((page.height_mm - p.y) / o.step_mm)};
  };

  StepCounts counts;
  Tape tape;
  GridPoint at{0, 0};
  auto travel = [&](GridPoint to, bool down) {
    const std::string steps = plotter_steps(at, to, o.knights_move_correction);
    (down ? counts.pen_down_steps : counts.pen_up_steps) += steps.size();
    if (counts.pen_down_steps + counts.pen_up_steps > kMaxSteps)
      throw DeviceError("the drawing needs more than 200 million plotter steps; use a larger step");
    for (const char c : steps) tape.push(c);
    at = to;
  };
  for (const PlotStroke& stroke : page.strokes) {
    if (stroke.points.empty()) continue;
    travel(to_grid(stroke.points.front()), false);
    tape.pen('D');
    ++counts.lifts;
    for (std::size_t i = 1; i < stroke.points.size(); ++i) travel(to_grid(stroke.points[i]), true);
    tape.pen('U');
  }
  travel({0, 0}, false);
  tape.pen('S');

  char header[400];
  std::snprintf(header, sizeof header,
                "# hlrscript incremental plotter tape (eight directions, 1 = +y clockwise to 8 = -x+y; U up, "
                "D down, 0 nothing, S stop)\n# step %g mm, sheet %g x %g mm, origin bottom-left, y up\n"
                "# %zu pen-down steps, %zu pen-up steps, %zu strokes\n",
                o.step_mm, page.width_mm, page.height_mm, counts.pen_down_steps, counts.pen_up_steps,
                counts.lifts);
  if (counts_out) *counts_out = counts;
  return header + tape.finish();
}

void write_plotter_steps(const std::filesystem::path& target, const PlotPage& page,
                         const StepOptions& options) {
  std::string text;
  try {
    text = to_plotter_steps(page, options);
  } catch (const DeviceError& e) {
    throw DeviceError("cannot write '" + target.string() + "': " + e.what());
  }
  write_atomically(target, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw DeviceError("write failed");
  });
}

}  // namespace hlr
