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
//                "segments": [{"p": [[x,y,z],[x,y,z]], "s": [[u,v],[u,v]], "object": "name",
//                              "edge": i | "other": "name", "hidden": false}],
//                "strokes": [[[x_mm,y_mm], ...], ...],
//                "hidden_strokes": [...] (only with include_hidden),
//                "stats": {"segments": n, "pen_down_mm": d, "pen_up_mm": u, "lifts": k}}]}
//
// Page coordinates: millimetres from the page's top-left corner, y down (as PDF and SVG, and the same
// numbers the PDF device draws at): page = origin_mm + mm_per_unit·(u, −v) for picture (u, v). The fit
// (core/device/page_layout.hpp) uses the camera frame, else every piece given, hidden or not, exactly
// as write_pdf does, so one frame lands at the same millimetres in both.
// camera: `eye` is the world point at the view origin — the eye for perspective, for orthographic a
// point on the view axis; `direction` is the unit world vector of increasing view depth (away from the
// eye). view_from_world maps world to (right, up, depth) as view = m·p + t; picture = focal·(right,
// up)/depth + offset (perspective) or focal·(right, up) + offset (orthographic).
// segments: pieces from an edge carry its index in the object's edge list; intersection lines carry
// the other object's name instead. Hidden pieces appear only with include_hidden.
// strokes: for now each visible piece is one stroke, in the engine's order, except that a piece whose
// start equals the previous piece's end (both snapped to 1e-6 mm) continues that stroke; pieces that
// snap to zero length are left out. Pen planning will reorder and join them. stats describe "strokes":
// pen_down_mm their summed length, pen_up_mm the travel from the page origin (0, 0) to the first
// stroke, between consecutive strokes and back to the origin, lifts the number of strokes; "segments"
// counts the visible pieces.
// Numbers are finite (a non-finite input is a DeviceError) and printed by nlohmann::json, whose
// shortest-representation output reads back to the identical double. The text is deterministic:
// keys in schema order, no time stamps.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/device/page_layout.hpp"
#include "core/hlr/visible_segment.hpp"

namespace hlr {

inline constexpr const char* kJsonLinesFormat = "hlrscript.lines/1";

struct JsonFrame {
  int frame = 0;
  double time = 0;  // seconds
  Camera camera;
  std::vector<VisibleSegment> segments;
  std::vector<std::string> object_names;  // indexed by VisibleSegment::object (and ::other)
};

struct JsonOptions {
  Paper paper;  // A4 landscape
  double margin_mm = 12;
  bool include_hidden = false;
  std::string title;  // omitted when empty
  // true: indented, one segment or stroke per line; false: a single line without spaces.
  bool pretty = true;
};

// Throws DeviceError for a non-finite number, an object index without a name, or a bad paper/margin.
std::string to_json_text(const std::vector<JsonFrame>& frames, const JsonOptions& options);

// Atomic (core/device/atomic_file.hpp): on any error nothing is left at `target`, and DeviceError names it.
void write_json(const std::filesystem::path& target, const std::vector<JsonFrame>& frames,
                const JsonOptions& options);

}  // namespace hlr
