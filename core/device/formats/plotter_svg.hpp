// Plotter SVG: a PlotPage as an SVG that pen-plotter software reads as a plan — written by us, not cairo.
//
// What AxiDraw's software (Inkscape extension, axicli), vpype and Inkscape itself take from an SVG:
// layers are `<g inkscape:groupmode="layer">` whose label starts with a number (AxiDraw's layer mode plots
// "all layers whose name begins with N"), paths are stroked outlines, and the document's width/height in
// mm with a matching viewBox fix the scale. So the file holds, and draws, nothing but the strokes:
//   - one layer per pen, in pen order, labelled "N colour" (N the pen number: "1 black", "2 #cc3300"), and
//     the hidden strokes of a pen in a layer of their own after it, "N hidden" (dashed on screen; a plotter
//     that ignores dashes draws them whole, as the JSON strokes are); drawn by occlusion level, a layer
//     per level instead, "N hidden K" for level K, levels ascending, each dashed in its level's pattern
//     (core/device/page/page_style.hpp); the visible pieces of hatch lines in a layer "N hatch" after them;
//   - in each layer one `<path>` per planned stroke, in planned order (ids s0, s1, … in the order of
//     PlotPage::strokes), `fill="none"`, the pen's colour and width, round caps and joins;
//   - no border, no background, no caption glyphs (text arrives as ordinary strokes, single-stroke).
// Coordinates are page millimetres (top-left origin, y down, one user unit = 1 mm), written to 0.001 mm —
// finer than any plotter's step. A point off the page is an error unless `clip`, which cuts strokes at
// the page's edge (the pen cannot leave the sheet either).
#pragma once

#include <string>

#include "core/device/page/pen_style.hpp"
#include "core/device/page/plot_page.hpp"

namespace hlr {

struct PlotterSvgOptions {
  PenTable pens;      // colours and widths of the layers' strokes
  std::string title;  // the document's <title> (not drawn)
  bool clip = false;  // cut strokes at the page's edge instead of refusing points off it
};

// The page's layer label for `pen`: "1 black", "2 red", "9 #1a2b3c"; hidden: "2 hidden", and with an
// occlusion level (level > 0) "2 hidden 3"; hatching: "3 hatch".
std::string plotter_svg_layer_label(int pen, const PenStyle& style, StrokeLayer layer, int level = 0);

// Throws DeviceError: a page that is not finite and positive, a point that is not finite, a point off the
// page without `clip`.
std::string to_plotter_svg(const PlotPage& page, const PlotterSvgOptions& options);

}  // namespace hlr
