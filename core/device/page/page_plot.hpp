// One frame's visible set laid out on its page and pen-planned: the PlotPage every device draws, the
// layout that put it there (for JSON readers mapping picture to page) and the plan's statistics.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/device/page/dimension_strokes.hpp"
#include "core/device/page/hidden_style.hpp"
#include "core/device/page/page_layout.hpp"
#include "core/device/page/plot_page.hpp"
#include "core/geometry/rect2.hpp"
#include "core/hlr/visible_segment.hpp"
#include "core/plan/hidden_dashes.hpp"
#include "core/plan/pen_plan.hpp"

namespace hlr {

// Single-stroke text placed on the page (a `label ... at page (x, y)`): its baseline starts at `at`.
struct PageText {
  std::string text;
  Point2 at;             // page mm, top-left, y down
  double size_mm = 3.5;  // capitals' height
  int pen = 1;
};

struct PagePlotOptions {
  PageSpec spec;                 // paper, margins, explicit scale
  std::vector<int> object_pens;  // by VisibleSegment::object; objects past the end use pen 1
  // Pen of hidden pieces; unset: the object's pen. Drawn by occlusion level, level k is in pen
  // hidden_pen + k − 1 (a pen past kMaxPen is a DeviceError).
  std::optional<int> hidden_pen;
  // Pen of hatch pieces (VisibleSegment::hatch), by object; 0, or objects past the end: the object's pen.
  std::vector<int> hatch_pens;
  // Hidden pieces are planned (and drawn) only when hidden.drawn(); by level (Levels), those of levels
  // 1..hidden.levels, each PlotPiece carrying its level; plain dashed ones at level 0.
  HiddenStyle hidden;
  PlanOptions plan;
  // The caption as single-stroke text (core/device/page/stroke_text.hpp) in pen 1, planned with the drawing,
  // instead of a string the device prints (plotters, and --text stroke), in the bottom margin.
  bool caption_as_strokes = false;
  // The pen reaches no closer to the sheet's edge (DevicePlanning::min_margin_mm).
  double reach_margin_mm = 0;
  std::vector<PageText> texts;            // drawn and planned with the rest
  std::vector<PageDimension> dimensions;  // a sheet's (plot_sheet), each in its view
  // What the layout fits instead of the frame or the pieces: fixed before labels were added, so that
  // they never move the drawing.
  std::optional<Rect2> extent;
  // Plotters: hidden strokes cut into pen-down dashes of this pattern after planning (they have no
  // dashed line of their own); unset: hidden strokes stay whole (the cairo devices dash them as they draw).
  std::optional<DashPattern> hidden_dashes;
};

// The caption's size in stroke text: about the 10 pt of the printed caption.
inline constexpr double kCaptionCapHeightMm = 2.5;
// The bottom margin a stroke caption needs beyond the pen's reach: descenders, caps and a gap above them.
inline constexpr double kCaptionBandMm = kCaptionCapHeightMm * (1 + 7.0 / 21.0) + 1;

struct PagePlot {
  PlotPage page;
  PageLayout layout;
  PlanStats stats;
  std::size_t visible_segments = 0;  // visible pieces given (before snapping and merging)
  // Drawn by occlusion level: [k] the hidden pieces of level k given (index 0 unused); else empty.
  std::vector<std::size_t> level_pieces;
  // A sheet (plot_sheet): each view on the page, mm — its camera frame, else the bounds of what it draws,
  // with its label; empty for a view that draws nothing.
  std::vector<Rect2> view_boxes;
  // A sheet: by PagePlotOptions::dimensions, why one was not drawn (empty when it was).
  std::vector<std::string> dimension_problems;
};

// Fits the drawing (the camera frame when there is one, else the pieces) to the page, maps every piece
// to page millimetres and plans the strokes. Throws DeviceError for a bad page, a non-finite coordinate or
// a pen outside 1..255 (a hidden level's pen included).
PagePlot plot_page(const std::vector<VisibleSegment>& segments, const std::optional<Rect2>& frame,
                   std::string caption, const PagePlotOptions& options);

// One view of a sheet (core/device/page/sheet_layout.hpp): a camera's drawing at its own place and scale.
struct SheetView {
  std::string name;
  Camera camera;                                   // as the engine drew it
  PageLayout layout;                               // picture to page
  double mm_per_world_unit = 1;                    // its scale (at the target's depth in perspective)
  std::size_t first_segment = 0, end_segment = 0;  // its pieces: [first, end) of the frame's segments
  std::string label;                               // written under the drawing; empty: none
};

// The sheet's frame and title block, drawn as strokes in pen 1 (so plotters draw them too).
struct SheetTitle {
  bool framed = true;  // false (--plain): neither frame nor title block
  std::string title;
  std::string scale;  // "1:2"
};

// A sheet: every view's pieces laid out by its own layout, each view's label under it, the frame and title
// block, planned as one page. `options.extent` and the caption are not used. Throws as plot_page() does.
PagePlot plot_sheet(const std::vector<VisibleSegment>& segments, const std::vector<SheetView>& views,
                    const SheetTitle& title, const PagePlotOptions& options);

}  // namespace hlr
