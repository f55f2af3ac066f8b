#include "core/device/formats/devices.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/device/page/atomic_file.hpp"

namespace hlr {

namespace fs = std::filesystem;

std::optional<DeviceKind> device_kind_for(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".pdf") return DeviceKind::Pdf;
  if (ext == ".svg") return DeviceKind::Svg;
  if (ext == ".png") return DeviceKind::Png;
  if (ext == ".hpgl" || ext == ".plt" || ext == ".hpg") return DeviceKind::Hpgl;
  if (ext == ".steps") return DeviceKind::Steps;
  if (ext == ".json") return DeviceKind::Json;
  if (ext == ".jsonl") return DeviceKind::JsonLines;
  if (ext == ".gcode" || ext == ".nc" || ext == ".ngc") return DeviceKind::Gcode;
  if (ext == ".dxf") return DeviceKind::Dxf;
  if (ext == ".off") return DeviceKind::Off;
  if (ext == ".obj") return DeviceKind::Obj;
  if (ext == ".stl") return DeviceKind::Stl;
  return std::nullopt;
}

const char* device_kind_name(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::Pdf:
      return "PDF";
    case DeviceKind::Svg:
      return "SVG";
    case DeviceKind::Png:
      return "PNG";
    case DeviceKind::Hpgl:
      return "HPGL";
    case DeviceKind::Steps:
      return "plotter-steps";
    case DeviceKind::Json:
      return "JSON";
    case DeviceKind::JsonLines:
      return "JSON Lines";
    case DeviceKind::Gcode:
      return "G-code";
    case DeviceKind::Dxf:
      return "DXF";
    case DeviceKind::Off:
      return "OFF";
    case DeviceKind::Obj:
      return "OBJ";
    case DeviceKind::Stl:
      return "STL";
  }
  return "?";
}

bool one_frame_per_file(DeviceKind kind) {
  return kind != DeviceKind::Pdf && kind != DeviceKind::Json && kind != DeviceKind::JsonLines;
}

bool writes_solids(DeviceKind kind) {
  return kind == DeviceKind::Off || kind == DeviceKind::Obj || kind == DeviceKind::Stl;
}

const char* supported_extensions() {
  return "pdf, svg, png, hpgl (or .plt), steps, json, jsonl, gcode (or .nc), dxf, off, obj, stl";
}

namespace {

// A file that gets its frames' bytes as they come.
class ByteFile : public DeviceFile {
 public:
  explicit ByteFile(const fs::path& path) {
    errno = 0;
    out_.open(path, std::ios::binary | std::ios::trunc);
    if (!out_) fail("cannot create a file in '" + path.parent_path().string() + "'");
  }
  void append(EncodedFrame frame) override {
    if (!frame.file_head.empty() && first_) write(frame.file_head);
    write(frame.bytes);
    first_ = false;
  }
  void finish() override {
    errno = 0;
    out_.close();
    if (!out_) fail("the write failed");
  }

 protected:
  void write(const std::string& bytes) {
    errno = 0;
    out_.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out_) fail("the write failed");
  }
  // The system's reason (no space left on the device, permission denied, file too large) is what the
  // user can act on; the temporary file's name is not.
  [[noreturn]] static void fail(const std::string& what) {
    const int e = errno;
    throw DeviceError(e ? what + ": " + std::strerror(e) : what);
  }
  bool first_ = true;

 private:
  std::ofstream out_;
};

// Pages planned on the page itself: the grid, the page's top-left corner, the generic plotter's speeds.
DevicePlanning page_planning() {
  DevicePlanning p;
  p.speeds = hpgl_profile_by_name("generic")->speeds;
  return p;
}

// A device whose file is one frame's page, as bytes made from the page alone.
class OneFrameDevice : public Device {
 public:
  bool one_frame_per_file() const override { return true; }
  EncodedFrame encode(const DeviceFrame& frame) const final {
    EncodedFrame out;
    out.bytes = page_bytes(frame.plot.page);
    return out;
  }
  virtual std::string page_bytes(const PlotPage& page) const = 0;
  std::unique_ptr<DeviceFile> open(const fs::path& path) const override {
    return std::make_unique<ByteFile>(path);
  }
};

class CairoDevice : public OneFrameDevice {
 public:
  explicit CairoDevice(CairoOptions options) : o_(std::move(options)) {}
  const char* name() const override { return o_.format == CairoFormat::Svg ? "SVG" : "PNG"; }
  DevicePlanning planning(double, double) const override { return page_planning(); }
  std::string page_bytes(const PlotPage& page) const override { return cairo_page_bytes(page, o_); }

 private:
  CairoOptions o_;
};

class PlotterSvgDevice : public OneFrameDevice {
 public:
  explicit PlotterSvgDevice(PlotterSvgOptions options) : o_(std::move(options)) {}
  const char* name() const override { return "SVG"; }
  DevicePlanning planning(double, double) const override {
    DevicePlanning p = page_planning();
    p.text_as_strokes = true;
    return p;
  }
  std::string page_bytes(const PlotPage& page) const override { return to_plotter_svg(page, o_); }

 private:
  PlotterSvgOptions o_;
};

class PdfDevice : public Device {
 public:
  explicit PdfDevice(PdfOptions options) : o_(std::move(options)) {}
  const char* name() const override { return "PDF"; }
  bool one_frame_per_file() const override { return false; }
  DevicePlanning planning(double, double) const override { return page_planning(); }
  EncodedFrame encode(const DeviceFrame& frame) const override {
    PdfPage page = make_pdf_page(frame.plot.page, o_);
    EncodedFrame out;
    out.content_streams = std::move(page.contents);
    out.page_width_mm = page.width_mm;
    out.page_height_mm = page.height_mm;
    return out;
  }
  std::unique_ptr<DeviceFile> open(const fs::path& path) const override {
    return std::make_unique<PdfFile>(path, o_);
  }

 private:
  class PdfFile : public DeviceFile {
   public:
    PdfFile(const fs::path& path, const PdfOptions& o) : pdf_(path, o) {}
    void append(EncodedFrame frame) override {
      pdf_.add_page({frame.page_width_mm, frame.page_height_mm, std::move(frame.content_streams)});
    }
    void finish() override { pdf_.finish(); }

   private:
    PdfWriter pdf_;
  };
  PdfOptions o_;
};

class HpglDevice : public OneFrameDevice {
 public:
  HpglDevice(HpglProfile profile, HpglOptions options)
      : profile_(std::move(profile)), o_(std::move(options)) {
    check_hpgl_profile(profile_);
  }
  const char* name() const override { return "HPGL"; }
  DevicePlanning planning(double w, double h) const override {
    DevicePlanning p;
    p.grid_mm = profile_.unit_mm;
    p.speeds = profile_.speeds;
    // The pen reaches less than the whole sheet: the layout keeps to its reach, so the drawing stays
    // centred on the real sheet and never needs clipping; the pen starts at the plotter's origin.
    p.min_margin_mm = hpgl_min_margin_mm(profile_, w, h, o_.paper);
    p.home = hpgl_home_on_page(profile_, w, h, o_.paper);
    p.text_as_strokes = true;
    p.hidden_as_dashes = true;
    return p;
  }
  std::string page_bytes(const PlotPage& page) const override { return to_hpgl(page, profile_, o_); }

 private:
  HpglProfile profile_;
  HpglOptions o_;
};

class StepDevice : public OneFrameDevice {
 public:
  explicit StepDevice(StepOptions options) : o_(options) {}
  const char* name() const override { return "plotter-steps"; }
  DevicePlanning planning(double, double h) const override {
    // The thesis's Benson Lehner: steps at up to 2 cm/s, the pen starting at the sheet's corner.
    DevicePlanning p;
    p.grid_mm = o_.step_mm;
    p.home = {0, h};
    p.speeds = {20, 20, 0.1};
    p.hidden_as_dashes = true;
    return p;
  }
  std::string page_bytes(const PlotPage& page) const override { return to_plotter_steps(page, o_); }

 private:
  StepOptions o_;
};

class JsonDevice : public Device {
 public:
  explicit JsonDevice(JsonOptions options) : o_(std::move(options)) {}
  const char* name() const override { return "JSON"; }
  bool one_frame_per_file() const override { return false; }
  DevicePlanning planning(double, double) const override { return page_planning(); }
  EncodedFrame encode(const DeviceFrame& frame) const override {
    JsonOptions o = o_;
    o.include_hidden = o_.include_hidden || frame.hidden.drawn();
    o.levels = o.levels || frame.hidden.counts_levels();
    const JsonFrame f{frame.frame,
                      frame.time,
                      *frame.camera,
                      *frame.segments,
                      *frame.object_names,
                      frame.plot,
                      frame.views ? *frame.views : std::vector<SheetView>{}};
    EncodedFrame out;
    out.bytes = json_frame_text(f, o);
    out.file_head = json_document_head(frame.plot.page, o_);
    return out;
  }
  std::unique_ptr<DeviceFile> open(const fs::path& path) const override {
    return std::make_unique<JsonFile>(path, o_);
  }

 private:
  class JsonFile : public ByteFile {
   public:
    JsonFile(const fs::path& path, const JsonOptions& o) : ByteFile(path), o_(o) {}
    void append(EncodedFrame frame) override {
      if (first_) write(frame.file_head);
      write(json_frame_separator(first_, o_));
      write(frame.bytes);
      first_ = false;
      ++frames_;
    }
    void finish() override {
      if (first_) write(json_document_head(PlotPage{}, o_));
      write(json_document_tail(frames_, o_));
      ByteFile::finish();
    }

   private:
    JsonOptions o_;
    std::size_t frames_ = 0;
  };
  JsonOptions o_;
};

// ---- G-code ----------------------------------------------------------------------------------------

class GcodeDevice : public OneFrameDevice {
 public:
  GcodeDevice(GcodeProfile profile, GcodeOptions options) : profile_(std::move(profile)), o_(options) {
    check_gcode_profile(profile_);
  }
  const char* name() const override { return "G-code"; }
  DevicePlanning planning(double w, double h) const override {
    DevicePlanning p;
    p.grid_mm = kGcodeGridMm;
    p.speeds = gcode_speeds(profile_);
    p.home = gcode_home_on_page(profile_, w, h);  // throws for a page larger than the work area
    p.text_as_strokes = true;
    p.hidden_as_dashes = true;
    return p;
  }
  std::string page_bytes(const PlotPage& page) const override { return to_gcode(page, profile_, o_); }

 private:
  GcodeProfile profile_;
  GcodeOptions o_;
};

// ---- DXF -------------------------------------------------------------------------------------------

class DxfDevice : public OneFrameDevice {
 public:
  explicit DxfDevice(DxfOptions options) : o_(std::move(options)) {}
  const char* name() const override { return "DXF"; }
  DevicePlanning planning(double, double) const override {
    DevicePlanning p = page_planning();
    p.text_as_strokes = true;  // a CAD program or a cutter takes lines, not a font
    return p;                  // hidden strokes stay whole: their layer's linetype dashes them
  }
  std::string page_bytes(const PlotPage& page) const override { return to_dxf(page, o_); }

 private:
  DxfOptions o_;
};

}  // namespace

std::unique_ptr<DeviceFile> open_byte_file(const fs::path& path) { return std::make_unique<ByteFile>(path); }
DevicePlanning page_device_planning() { return page_planning(); }

std::unique_ptr<Device> make_dxf_device(const DxfOptions& options) {
  return std::make_unique<DxfDevice>(options);
}
std::unique_ptr<Device> make_gcode_device(const GcodeProfile& profile, const GcodeOptions& options) {
  return std::make_unique<GcodeDevice>(profile, options);
}
std::unique_ptr<Device> make_cairo_device(const CairoOptions& options) {
  if (options.format == CairoFormat::Pdf) return std::make_unique<PdfDevice>(pdf_options(options));
  return std::make_unique<CairoDevice>(options);
}
std::unique_ptr<Device> make_plotter_svg_device(const PlotterSvgOptions& options) {
  return std::make_unique<PlotterSvgDevice>(options);
}
std::unique_ptr<Device> make_hpgl_device(const HpglProfile& profile, const HpglOptions& options) {
  return std::make_unique<HpglDevice>(profile, options);
}
std::unique_ptr<Device> make_step_device(const StepOptions& options) {
  return std::make_unique<StepDevice>(options);
}
std::unique_ptr<Device> make_json_device(const JsonOptions& options) {
  return std::make_unique<JsonDevice>(options);
}

}  // namespace hlr
