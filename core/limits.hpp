// The numeric limits of drawings and devices, shared by core's checks and the runtime's (script settings,
// command-line options): one number each, so that what one side accepts the other never rejects, and
// messages print the number from here. The evaluator's runaway limits stay in runtime/base/limits.hpp.
#pragma once

namespace hlr {

// ---- Pens
// Pen numbers run 1…kMaxPen: one byte, far more than any carousel or colour table.
inline constexpr int kMaxPen = 255;
// Occlusion levels drawn run 1…kMaxOcclusionLevel: past a few surfaces a plotter drawing is a thicket, and
// each level is a layer (and on plotters a pen) of its own.
inline constexpr int kMaxOcclusionLevel = 16;
// Hatch lines laid by one hatch() call: a million lines is already a day's plotting.
inline constexpr double kMaxHatchLines = 1e6;
// The widest pen line: beyond a centimetre a stroke is no longer a line.
inline constexpr double kMaxPenWidthMm = 10;

// ---- Paper
// The largest sheet side (10 m: far beyond any plotter, well inside cairo's coordinate range).
inline constexpr double kMaxPaperSideMm = 10000;

// Millimetres per picture unit of an explicit scale (--scale): far past any drawing either way.
inline constexpr double kMinMmPerUnit = 1e-9;
inline constexpr double kMaxMmPerUnit = 1e9;

// ---- HPGL plotters
// VS velocity in cm/s, the range core/device/formats/hpgl_device.hpp documents. A plotter clamps a VS above
// its own top speed (38.1 cm/s on the HP 7475A, 80 on the 7550A), so the cap only rejects nonsense.
inline constexpr double kMinVelocityCmS = 0.01;
inline constexpr double kMaxVelocityCmS = 1000;
// Millimetres per plotter unit: real plotters step 0.025 mm (HP, Roland) or 0.01 mm (cutters).
inline constexpr double kMinPlotterUnitMm = 0.001;
inline constexpr double kMaxPlotterUnitMm = 1;
// Coordinate pairs per PD command: small interpreter buffers want few; more than this helps none.
inline constexpr int kMaxPairsPerPd = 10000;
// HP-GL integer coordinates are 16-bit.
inline constexpr long kHpglMinCoordinate = -32768;
inline constexpr long kHpglMaxCoordinate = 32767;
// The longest relative step written, kept under kHpglMaxCoordinate with margin for rounding.
inline constexpr long kHpglMaxStep = 32000;

// ---- Incremental plotter tape (.steps)
// Step length in mm: a micrometre is below any stepper's resolution, a centimetre no longer draws.
inline constexpr double kMinPlotterStepMm = 0.001;
inline constexpr double kMaxPlotterStepMm = 10;

// ---- G-code (GRBL pen plotters)
// Feeds in mm/min: 100 m/min is beyond any pen plotter's motors; a feed below 1 mm/min never finishes.
inline constexpr double kMinGcodeFeedMmMin = 1;
inline constexpr double kMaxGcodeFeedMmMin = 100000;
// A dwell longer than 10 s is no longer waiting for a pen to settle.
inline constexpr double kMaxGcodeDwellS = 10;
// Spindle S values (servo pens: GRBL's $30 maximum is 1000 by default; some builds use pulse widths in µs).
inline constexpr double kMaxGcodeSpindle = 100000;
// Z positions of a Z-axis pen, mm either side of the work origin.
inline constexpr double kMaxGcodeZMm = 1000;

}  // namespace hlr
