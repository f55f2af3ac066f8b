// DXF: a PlotPage as a drawing for CAD programs and laser cutters — written by us, in the oldest DXF that
// every reader takes (AutoCAD R12, AC1009: LibreCAD, QCAD, ezdxf, Inkscape, LightBurn, the cutters' own
// software), not through a library: a page of polylines needs four sections of text.
//
// What the file holds:
//   - the header: AC1009, millimetres ($INSUNITS 4, $MEASUREMENT 1), the page as limits and extents;
//   - a linetype per hidden pattern, "HIDDEN" for plain dashed hidden lines and "HIDDEN2" … for deeper
//     occlusion levels, in the dashes the PDF shows (core/device/page/page_style.hpp), and CONTINUOUS;
//   - a layer per pen and kind of stroke, named as plotter SVG's layers are but in the characters R12 allows:
//     "PEN1" for pen 1's visible strokes, "PEN1_HIDDEN" for its hidden ones (by occlusion level
//     "PEN1_HIDDEN_2" for level 2), "PEN1_HATCH" for its hatching; each in the AutoCAD colour index
//     nearest the pen's colour (7, black on white paper, for black) and its linetype;
//   - each planned stroke as one entity on its layer, in planned order: a LINE for two points, a POLYLINE
//     of VERTEX entities for more (closed when it ends where it starts);
//   - nothing else: no border, the caption as single-stroke text (DevicePlanning::text_as_strokes).
// Coordinates are page millimetres with the origin at the page's bottom-left corner and y up (DXF's way;
// the page's y runs down), written to 0.0001 mm. Hidden strokes stay whole: the linetype dashes them.
#pragma once

#include <string>

#include "core/device/page/pen_style.hpp"
#include "core/device/page/plot_page.hpp"

namespace hlr {

struct DxfOptions {
  PenTable pens;  // the pens' colours give the layers' colours
};

// The file's bytes. Throws DeviceError for a page that is not finite and positive or a point that is not
// finite.
std::string to_dxf(const PlotPage& page, const DxfOptions& options);

// The layer name of a stroke: "PEN1", "PEN1_HIDDEN", "PEN1_HIDDEN_2", "PEN1_HATCH".
std::string dxf_layer_name(const PlotStroke& stroke);

// The AutoCAD colour index (1–9: red, yellow, green, cyan, blue, magenta, black/white, dark and light
// grey) nearest `style`'s colour.
int dxf_colour_index(const PenStyle& style);

}  // namespace hlr
