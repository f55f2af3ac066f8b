// Writing one output target: every frame is laid out on its page and pen-planned once per file
// (core/device/page_plot.hpp), and the device draws those strokes in that order. PDF, SVG, PNG and JSON
// share one plan (page grid, home at the page's top-left corner); HPGL and the stepping tape are planned
// on their own grid from their own home (the plotter's origin), so they draw the same lines, possibly in
// another order. Settings: the command line's DeviceOptions override the script's (paper, pens,
// plotter).
#include <algorithm>
#include <cstdio>

#include "core/device/atomic_file.hpp"
#include "core/device/cairo_device.hpp"
#include "core/device/hpgl_device.hpp"
#include "core/device/json_device.hpp"
#include "core/device/page_plot.hpp"
#include "core/device/pen_style.hpp"
#include "core/device/step_device.hpp"
#include "runtime/eval_error.hpp"
#include "runtime/output_plan.hpp"

namespace hlr::runtime {

namespace fs = std::filesystem;

namespace {

std::string caption_for(const FrameOutput& f, const WriteOptions& options) {
  char buf[256];
  if (options.frame_count > 1)
    std::snprintf(buf, sizeof buf, "%s   frame %d of %d (t = %.4g, %.4g s)   camera %s",
                  options.title.c_str(), f.time.frame, options.frame_count, f.time.t, f.time.time,
                  f.camera_name.c_str());
  else
    std::snprintf(buf, sizeof buf, "%s   camera %s", options.title.c_str(), f.camera_name.c_str());
  return buf;
}

// The page of a target: the first frame's paper setting (frames of one file share the page), with the
// command line's paper, orientation, margin and scale taking precedence.
PageSpec page_spec_for(const FrameOutput& first, const DeviceOptions& d) {
  PageSpec spec;
  if (first.paper) {
    spec.paper = first.paper->paper;
    if (first.paper->margin_mm) spec.margin_mm = *first.paper->margin_mm;
    spec.mm_per_unit = first.paper->mm_per_unit;
  }
  if (d.paper) {
    const bool landscape = d.landscape.value_or(true);
    const std::optional<Paper> paper = parse_paper(*d.paper, landscape);
    if (!paper)  // the CLI checked the spelling; this is a safety net
      throw RunError("--paper " + *d.paper + ": unknown paper size",
                     "use A0-A6, Letter, Legal, Tabloid or WxH in mm", 64);
    spec.paper = *paper;
  } else if (d.landscape) {
    const bool is_landscape = spec.paper.width_mm >= spec.paper.height_mm;
    if (is_landscape != *d.landscape) std::swap(spec.paper.width_mm, spec.paper.height_mm);
  }
  if (d.margin_mm) spec.margin_mm = *d.margin_mm;
  if (d.mm_per_unit) spec.mm_per_unit = d.mm_per_unit;
  return spec;
}

// The HPGL profile: --plotter, else the script's `output ... plotter NAME`, else the generic HP-GL
// profile. Names are looked up among the script's declared plotters first, then the built-in ones.
HpglProfile plotter_for(const FrameOutput& first, const DeviceOptions& d) {
  const bool from_cli = d.plotter.has_value();
  const std::optional<std::string> wanted = from_cli       ? d.plotter
                                            : first.output ? first.output->plotter
                                                           : std::nullopt;
  if (!wanted) return *hpgl_profile_by_name("generic");
  for (const PlotterSetting& p : first.plotters)
    if (p.profile.name == *wanted) return p.profile;
  if (std::optional<HpglProfile> builtin = hpgl_profile_by_name(*wanted)) return *builtin;
  std::string declared;
  for (const PlotterSetting& p : first.plotters) declared += ", " + p.profile.name;
  const std::string message = "unknown plotter '" + *wanted + "'";
  const std::string hint = "plotters: " + hpgl_profile_list() + declared +
                           " (or declare one: plotter NAME { base: \"hp7475a\", ... })";
  if (!from_cli && first.output && first.output->plotter_span)
    fail(*first.output->plotter_span, message, hint);
  throw RunError((from_cli ? "--plotter: " : "") + message, hint, 64);
}

PenTable pen_table_for(const FrameOutput& first, const DeviceOptions& d) {
  PenTable table;
  if (d.line_width_mm) table.set_default_width(*d.line_width_mm);
  for (const PenSetting& p : first.pens) {
    if (p.colour)
      if (const std::optional<Colour> colour = parse_colour(*p.colour)) table.set_colour(p.pen, *colour);
    if (p.width_mm && !d.line_width_mm) table.set_width(p.pen, *p.width_mm);
  }
  return table;
}

}  // namespace

void check_writable(const OutputTarget& target) {
  const fs::path dir = target.path.has_parent_path() ? target.path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))  // worded as write_atomically() words it
    throw DeviceError("cannot write '" + target.path.string() + "': directory '" + dir.string() +
                      "' does not exist");
}

std::vector<WrittenFrame> write_output(const OutputTarget& target, const std::vector<FrameOutput>& frames,
                                       const WriteOptions& options) {
  const DeviceOptions& d = options.device;
  const FrameOutput& first = frames[target.frames.front()];
  PagePlotOptions plot;
  plot.spec = page_spec_for(first, d);
  check_page_spec(plot.spec);
  plot.plan.order = d.pen_order;
  plot.plan.time_budget_ms = d.plan_budget_ms;
  std::optional<HpglProfile> profile;
  if (target.device == Device::Hpgl) {
    profile = plotter_for(first, d);
    if (d.relative) profile->relative = *d.relative;
    plot.plan.grid_mm = profile->unit_mm;
    plot.plan.speeds = profile->speeds;
    // The pen reaches less than the whole sheet: widen the margin to the plotter's reach, so the drawing
    // stays centred on the real sheet and never needs clipping.
    const double w = plot.spec.paper.width_mm, h = plot.spec.paper.height_mm;
    plot.spec.margin_mm = std::max(plot.spec.margin_mm, hpgl_min_margin_mm(*profile, w, h));
    check_page_spec(plot.spec);
    plot.plan.home = hpgl_home_on_page(*profile, w, h);
  } else if (target.device == Device::Steps) {
    // The thesis's Benson Lehner: 0.1 mm steps at up to 2 cm/s, the pen starting at the sheet's corner.
    plot.plan.grid_mm = d.step_mm;
    plot.plan.home = {0, plot.spec.paper.height_mm};
    plot.plan.speeds = {20, 20, 0.1};
  } else {
    plot.plan.speeds = hpgl_profile_by_name("generic")->speeds;
  }

  std::vector<PagePlot> plots;
  std::vector<WrittenFrame> written;
  plots.reserve(target.frames.size());
  for (const std::size_t i : target.frames) {
    const FrameOutput& f = frames[i];
    plot.object_pens = f.object_pens;
    plot.hidden_pen = f.hidden_pen;
    plot.include_hidden = f.hidden;
    plots.push_back(plot_page(f.segments, f.camera.frame, caption_for(f, options), plot));
    written.push_back({f.time.frame, plots.back().stats, plots.back().visible_segments});
  }

  switch (target.device) {
    case Device::Pdf:
    case Device::Svg:
    case Device::Png: {
      CairoOptions cairo;
      cairo.format = target.device == Device::Pdf   ? CairoFormat::Pdf
                     : target.device == Device::Svg ? CairoFormat::Svg
                                                    : CairoFormat::Png;
      cairo.pens = pen_table_for(first, d);
      cairo.dpi = d.dpi;
      cairo.decorations = d.decorations;
      cairo.title = options.title;
      std::vector<PlotPage> pages;
      pages.reserve(plots.size());
      for (PagePlot& p : plots) pages.push_back(std::move(p.page));
      write_cairo(target.path, pages, cairo);
      break;
    }
    case Device::Hpgl: {
      HpglOptions hpgl;
      hpgl.clip = d.clip;
      write_hpgl(target.path, plots.front().page, *profile, hpgl);
      break;
    }
    case Device::Steps: {
      StepOptions steps;
      steps.step_mm = d.step_mm;
      write_plotter_steps(target.path, plots.front().page, steps);
      break;
    }
    case Device::Json: {
      std::vector<JsonFrame> json;
      json.reserve(target.frames.size());
      JsonOptions o;
      o.title = options.title;
      o.pen_order = d.pen_order == PenOrder::None     ? "none"
                    : d.pen_order == PenOrder::Greedy ? "greedy"
                                                      : "optimized";
      for (std::size_t k = 0; k < target.frames.size(); ++k) {
        const FrameOutput& f = frames[target.frames[k]];
        json.push_back(
            {f.time.frame, f.time.time, f.camera, f.segments, f.object_names, std::move(plots[k])});
        o.include_hidden = o.include_hidden || f.hidden;
      }
      write_json(target.path, json, o);
      break;
    }
  }
  return written;
}

}  // namespace hlr::runtime
