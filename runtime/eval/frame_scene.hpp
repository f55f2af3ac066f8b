// What one evaluation of a script produces for one frame: the scene to draw, the cameras declared, and
// the settings statements (animate, output, paper, style). Plain data; no language types besides spans.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/device/page/dimension_strokes.hpp"
#include "core/device/page/hidden_style.hpp"
#include "core/device/page/page_layout.hpp"
#include "core/device/plotters/gcode_profile.hpp"
#include "core/device/plotters/hpgl_profile.hpp"
#include "core/hlr/scene.hpp"
#include "lang/ast.hpp"
#include "lang/diagnostic.hpp"
#include "runtime/values/frame_time.hpp"

namespace hlr::runtime {

struct NamedCamera {
  std::string name;
  Camera camera;
  lang::SourceSpan span;  // the `camera` statement
};

struct AnimationSetting {  // animate frames N fps F
  int frames = 1;
  double fps = kDefaultFps;
  lang::SourceSpan span;
};

struct OutputSetting {                 // output "pattern" [paper ...] [plotter NAME]
  std::string name;                    // the pattern evaluated for this frame
  bool interpolated = false;           // the pattern has {...}: each frame may name its own file
  lang::SourceSpan span;               // the pattern string
  std::optional<std::string> plotter;  // a declared plotter's or a built-in profile's name
  std::optional<lang::SourceSpan> plotter_span;
};

struct PaperSetting {  // paper A4 landscape [(margin: MM, scale: MM_PER_UNIT)], paper custom (width:,
                       // height:)
  std::string size;    // as written
  Paper paper;
  std::optional<double> margin_mm;
  std::optional<double> mm_per_unit;  // explicit scale instead of fit-to-page
  std::optional<PageFit> fit;         // fit: "camera" | "drawing"
  std::optional<std::string> title;   // title: a sheet's title block; else the script's file name
  lang::SourceSpan span;
};

struct PenSetting {  // pen N (colour: "red", width: 0.35)
  int pen = 1;
  std::optional<std::string> colour;  // as written, already checked to parse
  std::optional<double> width_mm;
  lang::SourceSpan span;
};

struct PlotterSetting {  // plotter NAME { base: "hp7475a", unit: 0.025, pens: 6, ... }
  HpglProfile profile;   // profile.name == NAME
  lang::SourceSpan span;
  // A G-code plotter (its base is a G-code profile: `base: "grbl-servo"`): then this is the profile and
  // `profile` above holds only the name.
  std::optional<GcodeProfile> gcode;
};

// label TEXT at [page] POINT [size: MM] [pen N]: single-stroke text at a world point (drawn flat on the
// page from where the point projects, hidden where the solids hide it) or at a page point.
inline constexpr double kDefaultLabelSizeMm = 3.5;  // capitals' height
inline constexpr double kMaxLabelSizeMm = 500;
struct LabelSetting {
  std::string text;
  Point3 at;  // world, or page mm (x, y) when on_page
  bool on_page = false;
  double size_mm = kDefaultLabelSizeMm;
  int pen = 1;
  lang::SourceSpan span;  // the statement
};

// view NAME = CAMERA at page (X, Y) [scale: S] [label: TEXT] [hidden: BOOL] [show: SOLIDS]: the camera's
// drawing on the sheet (runtime/pipeline/sheet_render.hpp), its picture origin — the camera's target — at
// page (X, Y) mm.
// Where `views of PART` puts a view: a cell of a grid the sheet's layout sizes and centres on the page
// (core/device/page/sheet_layout.hpp, grid_view_points), each column's views aligned along x and each row's
// along y, as projections are.
struct ViewGridCell {
  int column = 0, row = 0;
  double gap_mm = 20;  // between cells: room for dimensions
};

struct ViewSetting {
  NamedCamera camera;                 // the view's name, its camera and the statement's span
  Point2 at_mm;                       // page millimetres from the top-left corner, y down; unset in a grid
  std::optional<ViewGridCell> grid;   // placed by `views of`: at_mm comes from the layout
  std::optional<double> mm_per_unit;  // scale:; else the paper's, else the sheet's fitted scale
  std::string label;                  // label:; else the name in capitals ("": none)
  std::optional<bool> hidden;         // hidden:; else the sheet's style
  std::optional<Scene> shows;         // show:; what it draws instead of the script's drawn objects
  std::vector<int> show_pens;         // by shows' object: pen 1
  lang::SourceSpan name_span;
};

// dimension from P to Q [in VIEW] [offset:, direction:, text:, precision:, pen:]: drawn on the sheet in its
// view (core/device/page/dimension_strokes.hpp); the view is looked up when the sheet is laid out.
struct DimensionSetting {
  PageDimension dimension;  // its `view` is set from `view_name` by the pipeline
  std::optional<std::string> view_name;
  lang::SourceSpan view_span;  // the name after `in`, else the statement
  lang::SourceSpan span;       // the statement
};

struct FrameScene {
  FrameTime time;
  Scene scene;                       // drawn objects in draw order, names unique ("box", "box#2")
  std::vector<NamedCamera> cameras;  // in declaration order
  std::optional<AnimationSetting> animation;
  std::optional<OutputSetting> output;
  std::optional<PaperSetting> paper;
  std::optional<HiddenStyle> hidden;  // style hidden dashed | off | levels N
  std::optional<lang::SourceSpan> hidden_span;
  std::optional<int> hidden_pen;               // style hidden dashed|levels N pen P
  std::vector<int> object_pens;                // by scene object: draw ... pen N (default 1)
  std::optional<lang::SourceSpan> first_draw;  // what the first draw statement draws
  std::vector<PenSetting> pens;                // pen statements, each pen number at most once
  std::vector<PlotterSetting> plotters;        // declared plotters, names unique
  std::vector<LabelSetting> labels;            // in statement order
  std::vector<ViewSetting> views;              // in statement order, names unique; none: one camera's page
  std::vector<DimensionSetting> dimensions;    // in statement order
  std::vector<lang::Diagnostic> warnings;
  std::uint64_t steps = 0;
  std::size_t faces_built = 0;
  double evaluate_seconds = 0;
  // When the frame's --frame-timeout runs out, counted from the start of its evaluation.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
};

}  // namespace hlr::runtime
