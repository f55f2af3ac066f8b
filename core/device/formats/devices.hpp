// The devices behind the Device interface (core/device/page/device.hpp), each made from its own settings.
#pragma once

#include <memory>

#include "core/device/formats/cairo_device.hpp"
#include "core/device/formats/dxf_device.hpp"
#include "core/device/formats/gcode_device.hpp"
#include "core/device/formats/hpgl_device.hpp"
#include "core/device/formats/json_device.hpp"
#include "core/device/formats/plotter_svg.hpp"
#include "core/device/formats/step_device.hpp"
#include "core/device/page/device.hpp"

namespace hlr {

// PDF (any number of pages; core/device/formats/pdf_writer.hpp), SVG or PNG (one each), as options.format
// says. Planned on the page grid from the page's top-left corner, with the generic plotter's speeds for the
// time estimate.
std::unique_ptr<Device> make_cairo_device(const CairoOptions& options);
// SVG for pen plotters (core/device/formats/plotter_svg.hpp): layers per pen, one path per planned stroke.
// Planned as the cairo devices are.
std::unique_ptr<Device> make_plotter_svg_device(const PlotterSvgOptions& options);
// HP-GL for `profile`: planned in its plotter units from its origin, within the margin its reach needs.
std::unique_ptr<Device> make_hpgl_device(const HpglProfile& profile, const HpglOptions& options = {});
// The incremental plotter's tape: planned on its step grid from the sheet's bottom-left corner.
std::unique_ptr<Device> make_step_device(const StepOptions& options = {});
// hlrscript.lines/1, any number of frames; planned as the cairo devices are.
std::unique_ptr<Device> make_json_device(const JsonOptions& options);
// DXF for CAD programs and laser cutters (core/device/formats/dxf_device.hpp); planned as the cairo devices
// are, the caption in single strokes, hidden strokes whole.
std::unique_ptr<Device> make_dxf_device(const DxfOptions& options);
// G-code for a GRBL pen plotter `profile`: planned on kGcodeGridMm from the machine's origin on the page,
// with the profile's feeds and dwells for the time estimate.
std::unique_ptr<Device> make_gcode_device(const GcodeProfile& profile, const GcodeOptions& options = {});

// For devices made elsewhere (mesh export, stdlib/mesh_export.hpp): a file that takes each frame's bytes
// as they come, and the planning of a page that goes to no plotter.
std::unique_ptr<DeviceFile> open_byte_file(const std::filesystem::path& path);
DevicePlanning page_device_planning();

}  // namespace hlr
