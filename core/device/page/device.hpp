// The one interface every output device implements (PDF, SVG, PNG, HPGL, the stepping tape, JSON).
//
// A device says how its pages are to be planned (grid, where the pen starts, how fast it moves, how much
// of the sheet it reaches) and whether a file holds one frame or many. The frame pipeline
// (runtime/pipeline/frame_pipeline.cpp) then runs, for every frame and in parallel with other frames,
//     page layout + pen plan (core/device/page/page_plot.hpp) with planning() → encode()
// and, one frame after another in frame order, appends what encode() made to the file open() returned.
// encode() does everything that does not depend on the frames before (PNG rasterising and compression,
// SVG and HPGL text, a JSON frame's text, a PDF page's compressed content stream), so the part that runs
// in order is little more than copying bytes; the output bytes are the same whatever the number of
// threads.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/device/page/page_plot.hpp"
#include "core/hlr/scene.hpp"
#include "core/hlr/visible_segment.hpp"

namespace hlr {

// How the pen plan of a page for this device is made (PlanOptions' device-given fields).
struct DevicePlanning {
  double grid_mm = 0.025;    // endpoints snap to the device's unit
  Point2 home{0, 0};         // where the pen starts and ends, page mm
  PlotterSpeeds speeds;      // for the plotting-time estimate
  double min_margin_mm = 0;  // the pen reaches no closer to the sheet's edge: the layout keeps this margin
  bool text_as_strokes = false;   // plotters draw the caption as single-stroke text (--text overrides)
  bool hidden_as_dashes = false;  // plotters draw hidden strokes as planned pen-down dashes
};

// One frame, laid out and planned: what every device draws (plot) and what JSON also describes.
struct DeviceFrame {
  int frame = 0;
  double time = 0;  // seconds
  const Camera* camera = nullptr;
  const std::vector<VisibleSegment>* segments = nullptr;
  const std::vector<std::string>* object_names = nullptr;  // by VisibleSegment::object
  HiddenStyle hidden;  // JSON lists hidden pieces when drawn(), with their levels when counted
  PagePlot plot;
  // A sheet of views (runtime/pipeline/sheet_render.hpp): each view's camera, layout and share of
  // `segments`; null or empty for a page of one camera.
  const std::vector<SheetView>* views = nullptr;
  // The solids drawn, in world space (what mesh export writes); null where the caller has none.
  const Scene* scene = nullptr;
};

// A frame's share of a file, made by encode() on any thread.
struct EncodedFrame {
  std::string bytes;      // what the file gets for this frame (PDF: nothing, see content_streams)
  std::string file_head;  // JSON: the document's opening, written before the first frame
  double page_width_mm = 0, page_height_mm = 0;  // PDF: the page's size
  std::vector<std::string> content_streams;      // PDF: the page's compressed content, in parts
  std::size_t size() const {                     // bytes in all
    std::size_t n = bytes.size() + file_head.size();
    for (const std::string& s : content_streams) n += s.size();
    return n;
  }
};

// A file being written: frames arrive in frame order on one thread. finish() completes it; a file that
// is destroyed unfinished leaves whatever it wrote for the caller to remove.
class DeviceFile {
 public:
  virtual ~DeviceFile() = default;
  virtual void append(EncodedFrame frame) = 0;
  virtual void finish() = 0;
};

class Device {
 public:
  virtual ~Device() = default;
  virtual const char* name() const = 0;  // "PDF", "HPGL", ...: for messages
  // SVG, PNG, HPGL and the stepping tape hold one frame per file; PDF, JSON and JSON Lines any number.
  virtual bool one_frame_per_file() const = 0;
  // How a page of this size is planned for this device. Throws DeviceError (a page the plotter does
  // not take).
  virtual DevicePlanning planning(double page_width_mm, double page_height_mm) const = 0;
  // Thread-safe. Throws DeviceError for anything wrong with the frame (a point out of reach, a PNG too
  // large), before any file is touched.
  virtual EncodedFrame encode(const DeviceFrame& frame) const = 0;
  // Creates `path` (a temporary file the caller renames into place). Throws DeviceError.
  virtual std::unique_ptr<DeviceFile> open(const std::filesystem::path& path) const = 0;
};

// The file types, by extension (any case): .pdf .svg .png .hpgl/.plt/.hpg .steps .json, JSON Lines
// .jsonl, G-code .gcode/.nc/.ngc, .dxf, and the meshes .off .obj .stl (the solids, not the page).
enum class DeviceKind { Pdf, Svg, Png, Hpgl, Steps, Json, JsonLines, Gcode, Dxf, Off, Obj, Stl };
std::optional<DeviceKind> device_kind_for(const std::filesystem::path& path);
const char* device_kind_name(DeviceKind kind);  // "PDF", "SVG", ..., "plotter-steps", "JSON"
bool one_frame_per_file(DeviceKind kind);
// The meshes (.off, .obj, .stl): the frame's solids, not a picture of them (no camera or hidden lines
// needed).
bool writes_solids(DeviceKind kind);
// "pdf, svg, png, hpgl (or .plt), steps, json, jsonl, gcode (or .nc), dxf, off, obj, stl": for messages.
const char* supported_extensions();

}  // namespace hlr
