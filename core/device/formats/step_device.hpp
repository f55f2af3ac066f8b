// The incremental-plotter device: a PlotPage as the instruction tape of an eight-direction stepping
// plotter (the Benson Lehner of the Newcastle pen-up thesis, reference/004_penup.md §7), written as text.
//
// Instructions: '1'–'8' one step in a direction (clockwise from +y: 1 = +y, 2 = +x+y, 3 = +x, 4 = +x−y,
// 5 = −y, 6 = −x−y, 7 = −x, 8 = −x+y), 'U' pen up, 'D' pen down, '0' do nothing, 'S' stop reading. As on
// the original tape, three '0' follow every 'U', 'D' and 'S' to allow for mechanical travel, and the
// instructions come in rows of two (a row is padded with '0'). Each line of straight travel — drawn or
// with the pen up — is stepped by plotter_steps() with the Knight's-move correction, so a line drawn
// from B to A retraces A to B exactly.
//
// Coordinates: the pen starts at the sheet's bottom-left corner (the tape's origin), x to the right and
// y up, in steps of `step_mm`; every stroke point is snapped to the nearest step, and the pen returns
// to the origin before 'S'. The file starts with '#' comment lines (format, step, sheet, counts) and then
// holds the rows, separated by spaces, 32 rows per line.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "core/device/page/plot_page.hpp"

namespace hlr {

struct StepOptions {
  double step_mm = 0.1;  // the Benson Lehner's step
  bool knights_move_correction = true;
};

struct StepCounts {
  std::size_t pen_down_steps = 0, pen_up_steps = 0, lifts = 0;
};

// Throws DeviceError for a step that is not finite and in [0.001, 10] mm, a non-finite point, a point
// off the sheet, or a tape of more than 200 million steps.
std::string to_plotter_steps(const PlotPage& page, const StepOptions& options = {},
                             StepCounts* counts = nullptr);

// to_plotter_steps() written atomically.
void write_plotter_steps(const std::filesystem::path& target, const PlotPage& page,
                         const StepOptions& options = {});

}  // namespace hlr
