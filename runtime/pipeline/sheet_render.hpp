// A frame drawn as a sheet of views (`view NAME = CAMERA at page (X, Y) ...`,
// core/device/page/sheet_layout.hpp): each view's hidden lines from its own camera (its own frame clips it;
// hidden lines as its `hidden:` says, else as the sheet's style), then the layout — every view's scale, its
// own or the one fitted to the sheet — and the warnings a draughtsman wants: views that overlap each other or
// the title block, views that run off the page.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/device/page/page_plot.hpp"
#include "core/hlr/render_frame.hpp"
#include "lang/diagnostic.hpp"
#include "runtime/eval/frame_scene.hpp"

namespace hlr::runtime {

struct SheetDrawing {
  std::vector<VisibleSegment> segments;  // every view's, in view order (SheetView::first_segment ...)
  std::vector<SheetView> views;
  FrameStats stats;        // summed over the views
  std::string scale_text;  // the sheet's scale, "1:2"
  // The sheet's hidden style: the frame's, or dashed when it is off and a view asks for hidden lines.
  HiddenStyle hidden;
  // What views draw of their own (show:), numbered after the frame's drawn objects: their names, pens
  // and hatch pens, to append to the frame's.
  std::vector<std::string> shown_names;
  std::vector<int> shown_pens, shown_hatch_pens;
};

// Renders every view of `scene` through `render` (the pipeline's render_frame with its timeout handling)
// and lays them out on the page of `spec` (clear of the title block when `framed`), with room for
// `dimensions` (sheet_dimensions) beside the views they are drawn in. `hidden` is the sheet's style.
using ViewRenderer = std::function<FrameResult(const Scene&, const Camera&, const HlrOptions&)>;
SheetDrawing render_sheet(const FrameScene& scene, const PageSpec& spec, bool framed, HiddenStyle hidden,
                          const HlrOptions& hlr, const ViewRenderer& render,
                          const std::vector<PageDimension>& dimensions = {});

// The frame's dimensions, each with the index of its view: the one named after `in`, else the sheet's only
// view. Throws EvalError at the name for a view the sheet does not have, and at the statement when there
// are several views and none is named.
std::vector<PageDimension> sheet_dimensions(const FrameScene& scene);

// Warnings at the view statements: a view whose point is on or outside the margins, whose drawing runs
// off the page, or that overlaps a view before it or the title block (`boxes`: PagePlot::view_boxes).
std::vector<lang::Diagnostic> sheet_warnings(const FrameScene& scene, const PageSpec& spec,
                                             const std::vector<Rect2>& boxes, bool framed);

}  // namespace hlr::runtime
