// JSON device, schema "hlrscript.lines/1": for every frame the camera, the visible pieces in world and
// picture coordinates, and the strokes a plotter would draw, in page millimetres.
//
//   {"format": "hlrscript.lines/1", "title": "...",
//    "page": {"width_mm": 297, "height_mm": 210, "margin_mm": 12, "origin": "top-left", "y": "down"},
//    "frames": [{"frame": 0, "time": 0.0,
//                "camera": {"kind": "perspective" | "orthographic", "constructor": "lookat" | "ortho" | ...,
//                           "eye": [x,y,z], "direction": [dx,dy,dz], "focal": f, "offset": [u,v],
//                           "near_depth": n (perspective only), "frame": [xmin,ymin,xmax,ymax] (if any),
//                           "view_from_world": {"m": [[..],[..],[..]], "t": [..]}},
//                "layout": {"mm_per_unit": s, "origin_mm": [x,y]},
//                — or, for a sheet of views, instead of camera and layout:
//                "views": [{"name": "front", "label": "FRONT", "mm_per_world_unit": 0.5,
//                            "camera": {...}, "layout": {...}}, ...],
//                "segments": [{"p": [[x,y,z],[x,y,z]], "s": [[u,v],[u,v]], "object": "name",
//                              "edge": i | "other": "name" | "contour": f, "hatch": true (hatch lines),
//                              "hidden": false, "level": k (hidden, levels),
//                              "view": i (a sheet: the index of its view in "views")}],
//                "strokes": [[[x_mm,y_mm], ...], ...],
//                "stroke_pens": [1, ...] (the pen of each stroke),
//                "hatch_strokes": [...], "hatch_stroke_pens": [...] (only when the frame has hatching),
//                "hidden_strokes": [...], "hidden_stroke_pens": [...] (only with include_hidden),
//                "hidden_stroke_levels": [1, ...] (only with levels),
//                "stats": {"segments": n, "pen_down_mm": d, "pen_up_mm": u, "pen_up_mean_mm": m,
//                          "pen_up_median_mm": md, "lifts": k, "lift_lower_bound": b,
//                          "plot_seconds": t, "pen_order": "optimized"}}]}
//
// Page coordinates: millimetres from the page's top-left corner, y down (as PDF and SVG). Each frame
// carries its PagePlot (core/device/page/page_plot.hpp), which every device draws: "layout" is the fit its
// strokes were mapped with (the camera frame, else every piece given, hidden or not; see
// core/device/page/page_layout.hpp), page = origin_mm + mm_per_unit·(u, −v) for picture (u, v). "page" is
// the first frame's PlotPage size and margin (the frames of one file share their page).
// camera: `eye` is the world point at the view origin — the eye for perspective, for orthographic a
// point on the view axis; `direction` is the unit world vector of increasing view depth (away from the
// eye). view_from_world maps world to (right, up, depth) as view = m·p + t; picture = focal·(right,
// up)/depth + offset (perspective) or focal·(right, up) + offset (orthographic).
// segments: pieces from an edge carry its index in the object's edge list; intersection lines carry
// the other object's name instead; pieces of a smooth contour (contours: "smooth") the face they cross. Hidden pieces appear only with include_hidden. With levels (hidden
// lines drawn by occlusion level, `style hidden levels N`) each hidden segment carries "level": k, the
// number of surfaces in front of it (1..N), and "hidden_stroke_levels" the level of each hidden stroke;
// without, neither member is written (the document is as before levels existed). Pieces of hatch lines
// (hatch(), core/solid/hatching.hpp) are edge pieces that also carry "hatch": true; they are never hidden.
// strokes: the plot's visible-layer strokes (pen-planned by core/plan/pen_plan.hpp), in plotting order,
// with stroke_pens the pen of each; hidden_strokes and hidden_stroke_pens the hidden layer's, likewise;
// hatch_strokes and hatch_stroke_pens the hatching's, written only when there is some.
// The device neither reorders nor joins them. The plan draws pen by pen, visible before hidden within a
// pen, so on the plotter the two lists interleave when there are several pens. stats are the plan's
// (PlanStats), over every stroke it planned (both layers): pen_up_mm the travel from the home position
// to the first stroke, between strokes and back; lifts the strokes drawn and lift_lower_bound the fewest
// possible; plot_seconds the estimate from the plotter's speeds; pen_order is JsonOptions::pen_order as
// given; "segments" counts the frame's visible pieces (JsonFrame::segments).
// Parts (JsonOptions::parts, the command's --json LIST): "camera", "layout", "segments", "strokes" (with
// stroke_pens and the hidden lists) and "stats" may be left out; "frame" and "time" are always there.
// All are written by default.
// JSON Lines (JsonOptions::lines, a .jsonl file): no enclosing document; each frame is one line, a whole
// object holding the document's "format", "title" and "page" followed by the frame's own members, so a
// reader can stream the file or start at any line.
// Numbers are finite (a non-finite input is a DeviceError) and printed as the shortest text that reads
// back to the identical double (std::to_chars), whole numbers with ".0". The text is written straight
// from the frame (core/device/formats/json_text.hpp), deterministic: keys in schema order, no time stamps.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/device/page/page_plot.hpp"
#include "core/hlr/visible_segment.hpp"

namespace hlr {

inline constexpr const char* kJsonLinesFormat = "hlrscript.lines/1";

struct JsonFrame {
  int frame = 0;
  double time = 0;  // seconds
  Camera camera;
  std::vector<VisibleSegment> segments;
  std::vector<std::string> object_names;  // indexed by VisibleSegment::object (and ::other)
  PagePlot plot;                          // the frame laid out on its page and pen-planned
  std::vector<SheetView> views;           // a sheet's views; empty for a page of one camera
};

// Which of a frame's members are written.
struct JsonParts {
  bool camera = true, layout = true, segments = true, strokes = true, stats = true;
};

// "all", or a comma-separated list of camera, layout, segments, strokes, stats; nullopt for anything else.
std::optional<JsonParts> parse_json_parts(std::string_view list);

struct JsonOptions {
  bool include_hidden = false;          // list hidden segments and hidden_strokes
  bool levels = false;                  // with include_hidden: their occlusion levels too
  std::string pen_order = "optimized";  // reported in stats
  std::string title;                    // omitted when empty
  // true: indented, one segment or stroke per line; false: a single line without spaces.
  bool pretty = true;
  JsonParts parts;     // what each frame holds
  bool lines = false;  // JSON Lines: one compact frame per line, no enclosing document
};

// Throws DeviceError for a non-finite number (camera, segments, layout, strokes, stats), an object index
// without a name, a first-frame page that is not finite or leaves no room inside its margins
// (check_page_spec), or a name or title that is not valid UTF-8.
std::string to_json_text(const std::vector<JsonFrame>& frames, const JsonOptions& options);

// to_json_text() in pieces, for writing frame by frame: head + Σ (separator(i == 0) + frame_text) +
// tail(count) is to_json_text()'s text. The head describes the first frame's page. In JSON Lines the
// head, separators and tail are empty.
std::string json_document_head(const PlotPage& first_page, const JsonOptions& options);
std::string json_frame_text(const JsonFrame& frame, const JsonOptions& options);
std::string json_frame_separator(bool first, const JsonOptions& options);
std::string json_document_tail(std::size_t frames, const JsonOptions& options);

// Atomic (core/device/page/atomic_file.hpp): on any error nothing is left at `target`, and DeviceError names
// it.
void write_json(const std::filesystem::path& target, const std::vector<JsonFrame>& frames,
                const JsonOptions& options);

}  // namespace hlr
