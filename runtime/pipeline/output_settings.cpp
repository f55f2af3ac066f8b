#include "runtime/pipeline/output_settings.hpp"

#include <algorithm>
#include <cstdio>

#include "core/camera/lookat_camera.hpp"
#include "core/device/formats/devices.hpp"
#include "core/device/page/atomic_file.hpp"
#include "core/device/page/pen_style.hpp"
#include "core/limits.hpp"
#include "runtime/base/eval_error.hpp"
#include "runtime/pipeline/frame_pipeline.hpp"
#include "stdlib/mesh_export.hpp"

namespace hlr::runtime {

namespace {

std::string camera_list(const FrameScene& scene) {
  std::string out;
  for (const NamedCamera& c : scene.cameras) out += (out.empty() ? "" : ", ") + c.name;
  for (const ViewSetting& v : scene.views) out += (out.empty() ? "view " : ", view ") + v.camera.name;
  return out;
}

std::string caption_for(const FrameScene& scene, const NamedCamera& camera, const RunSettings& run) {
  char buf[256];
  if (run.frame_count > 1)
    std::snprintf(buf, sizeof buf, "%s   frame %d of %d (t = %.4g, %.4g s)   camera %s", run.title.c_str(),
                  scene.time.frame, run.frame_count, scene.time.t, scene.time.time, camera.name.c_str());
  else
    std::snprintf(buf, sizeof buf, "%s   camera %s", run.title.c_str(), camera.name.c_str());
  return buf;
}

// ---- G-code plotters (and the check that an output gets a plotter of its own kind) ----------------------

// A plotter named for an output of the other kind (an HPGL profile for a .gcode file, or the reverse):
// an error at the name, unless the name comes from the script's output statement and -o chose the file
// (then the script's plotter belongs to the script's own output, and the default is used).
void plotter_of_other_kind(const FrameScene& scene, bool from_cli, bool output_from_cli,
                           const std::string& name, const char* kind, const char* wanted_kind,
                           const std::string& choices) {
  if (!from_cli && output_from_cli) return;
  const std::string message =
      "plotter '" + name + "' is " + kind + " profile, but the output is " + wanted_kind;
  const std::string hint = std::string(wanted_kind) + " plotters: " + choices;
  if (!from_cli && scene.output && scene.output->plotter_span)
    fail(*scene.output->plotter_span, message, hint);
  throw RunError((from_cli ? "--plotter: " : "") + message, hint, 64);
}

std::string declared_gcode_plotters(const FrameScene& scene, bool gcode) {
  std::string out;
  for (const PlotterSetting& p : scene.plotters)
    if (p.gcode.has_value() == gcode) out += ", " + p.profile.name;
  return out;
}

// The G-code profile: --plotter, else the script's `output ... plotter NAME`, else grbl-servo; declared
// plotters first, then the built-in ones, as for HPGL.
GcodeProfile gcode_plotter_for(const FrameScene& scene, const RunSettings& run) {
  const DeviceOptions& d = run.device;
  const bool from_cli = d.plotter.has_value();
  const std::optional<std::string> wanted = from_cli       ? d.plotter
                                            : scene.output ? scene.output->plotter
                                                           : std::nullopt;
  const GcodeProfile standard = *gcode_profile_by_name("grbl-servo");
  if (!wanted) return standard;
  const std::string choices = gcode_profile_list() + declared_gcode_plotters(scene, true) +
                              " (or declare one: plotter NAME { base: \"grbl-servo\", ... })";
  for (const PlotterSetting& p : scene.plotters)
    if (p.profile.name == *wanted) {
      if (p.gcode) return *p.gcode;
      plotter_of_other_kind(scene, from_cli, run.output.has_value(), *wanted, "an HPGL", "G-code", choices);
      return standard;
    }
  if (std::optional<GcodeProfile> builtin = gcode_profile_by_name(*wanted)) return *builtin;
  if (hpgl_profile_by_name(*wanted)) {
    plotter_of_other_kind(scene, from_cli, run.output.has_value(), *wanted, "an HPGL", "G-code", choices);
    return standard;
  }
  const std::string message = "unknown plotter '" + *wanted + "'";
  const std::string hint = "G-code plotters: " + choices;
  if (!from_cli && scene.output && scene.output->plotter_span)
    fail(*scene.output->plotter_span, message, hint);
  throw RunError((from_cli ? "--plotter: " : "") + message, hint, 64);
}

// ---- HPGL plotters -------------------------------------------------------------------------------------

// The HPGL profile: --plotter, else the script's `output ... plotter NAME`, else the generic HP-GL
// profile. Names are looked up among the script's declared plotters first, then the built-in ones.
HpglProfile plotter_for(const FrameScene& scene, const DeviceOptions& d, bool output_from_cli) {
  const bool from_cli = d.plotter.has_value();
  const std::optional<std::string> wanted = from_cli       ? d.plotter
                                            : scene.output ? scene.output->plotter
                                                           : std::nullopt;
  if (!wanted) return *hpgl_profile_by_name("generic");
  const std::string hpgl_choices = hpgl_profile_list() + declared_gcode_plotters(scene, false);
  for (const PlotterSetting& p : scene.plotters)
    if (p.profile.name == *wanted) {
      if (!p.gcode) return p.profile;
      plotter_of_other_kind(scene, from_cli, output_from_cli, *wanted, "a G-code", "HPGL", hpgl_choices);
      return *hpgl_profile_by_name("generic");
    }
  if (std::optional<HpglProfile> builtin = hpgl_profile_by_name(*wanted)) return *builtin;
  if (gcode_profile_by_name(*wanted)) {
    plotter_of_other_kind(scene, from_cli, output_from_cli, *wanted, "a G-code", "HPGL", hpgl_choices);
    return *hpgl_profile_by_name("generic");
  }
  std::string declared;
  for (const PlotterSetting& p : scene.plotters)
    if (!p.gcode) declared += ", " + p.profile.name;
  const std::string message = "unknown plotter '" + *wanted + "'";
  const std::string hint = "plotters: " + hpgl_profile_list() + declared +
                           " (or declare one: plotter NAME { base: \"hp7475a\", ... })";
  if (!from_cli && scene.output && scene.output->plotter_span)
    fail(*scene.output->plotter_span, message, hint);
  throw RunError((from_cli ? "--plotter: " : "") + message, hint, 64);
}

PenTable pen_table_for(const FrameScene& scene, const DeviceOptions& d) {
  PenTable table;
  if (d.line_width_mm) table.set_default_width(*d.line_width_mm);
  for (const PenSetting& p : scene.pens) {
    if (p.colour)
      if (const std::optional<Colour> colour = parse_colour(*p.colour)) table.set_colour(p.pen, *colour);
    if (p.width_mm && !d.line_width_mm) table.set_width(p.pen, *p.width_mm);
  }
  return table;
}

const char* pen_order_name(PenOrder order) {
  return order == PenOrder::None ? "none" : order == PenOrder::Greedy ? "greedy" : "optimized";
}

std::shared_ptr<const Device> device_for(DeviceKind kind, const FrameScene& scene, const RunSettings& run) {
  const DeviceOptions& d = run.device;
  switch (kind) {
    case DeviceKind::Svg:
      // For a plotter when asked, or when the run names a plotter (it is going to one).
      if (d.plotter_svg.value_or(d.plotter.has_value() || (scene.output && scene.output->plotter))) {
        PlotterSvgOptions svg;
        svg.pens = pen_table_for(scene, d);
        svg.title = run.title;
        svg.clip = d.clip;
        return make_plotter_svg_device(svg);
      }
      [[fallthrough]];
    case DeviceKind::Pdf:
    case DeviceKind::Png: {
      CairoOptions cairo;
      cairo.format = kind == DeviceKind::Pdf   ? CairoFormat::Pdf
                     : kind == DeviceKind::Svg ? CairoFormat::Svg
                                               : CairoFormat::Png;
      cairo.pens = pen_table_for(scene, d);
      cairo.dpi = d.dpi;
      cairo.decorations = d.decorations;
      cairo.title = run.title;
      cairo.creation_date = d.creation_date;
      return make_cairo_device(cairo);
    }
    case DeviceKind::Hpgl: {
      HpglProfile profile = plotter_for(scene, d, run.output.has_value());
      if (d.relative) profile.relative = *d.relative;
      HpglOptions hpgl;
      hpgl.clip = d.clip;
      return make_hpgl_device(profile, hpgl);
    }
    case DeviceKind::Steps: {
      StepOptions steps;
      steps.step_mm = d.step_mm;
      return make_step_device(steps);
    }
    case DeviceKind::Gcode: {
      GcodeOptions gcode;
      gcode.clip = d.clip;
      return make_gcode_device(gcode_plotter_for(scene, run), gcode);
    }
    case DeviceKind::Dxf: {
      DxfOptions dxf;
      dxf.pens = pen_table_for(scene, d);
      return make_dxf_device(dxf);
    }
    case DeviceKind::Off:
      return stdlib::make_mesh_device(stdlib::MeshFormat::Off, run.title);
    case DeviceKind::Obj:
      return stdlib::make_mesh_device(stdlib::MeshFormat::Obj, run.title);
    case DeviceKind::Stl:
      return stdlib::make_mesh_device(stdlib::MeshFormat::Stl, run.title);
    case DeviceKind::Json:
    case DeviceKind::JsonLines: {
      JsonOptions json;
      json.lines = kind == DeviceKind::JsonLines;
      json.parts = d.json_parts;
      json.title = run.title;
      json.pen_order = pen_order_name(d.pen_order);
      return make_json_device(json);
    }
  }
  return nullptr;
}

}  // namespace

PageSpec page_spec_for(const FrameScene& scene, const DeviceOptions& d) {
  PageSpec spec;
  if (scene.paper) {
    spec.paper = scene.paper->paper;
    if (scene.paper->margin_mm) spec.margin_mm = *scene.paper->margin_mm;
    spec.mm_per_unit = scene.paper->mm_per_unit;
    if (scene.paper->fit) spec.fit = *scene.paper->fit;
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
  if (d.fit) spec.fit = *d.fit;
  return spec;
}

const NamedCamera& choose_camera(const FrameScene& scene, const std::optional<std::string>& wanted,
                                 const std::string& script_name) {
  if (scene.cameras.empty() && scene.views.empty()) {
    const std::string hint =
        "add one, for example: camera main = lookat(eye: (30, 20, 15), target: (0, 0, 0))";
    // At what is drawn, when something is: that is what the camera is missing for.
    if (scene.first_draw)
      fail(*scene.first_draw, "the script draws this but declares no camera to look at it", hint);
    throw RunError(script_name + ": the script declares no camera", hint, 65);
  }
  if (!wanted) return scene.views.empty() ? scene.cameras.back() : scene.views.front().camera;
  for (const NamedCamera& c : scene.cameras)
    if (c.name == *wanted) return c;
  for (const ViewSetting& v : scene.views)  // one view of a sheet, drawn alone on its page
    if (v.camera.name == *wanted) return v.camera;
  throw RunError("--camera " + *wanted + ": " + script_name + " declares no camera named '" + *wanted + "'",
                 "its cameras: " + camera_list(scene), 64);
}

namespace {

// The output goes to a mesh file (.off, .obj, .stl): the solids themselves, no picture.
bool writes_solids_only(const FrameScene& scene, const RunSettings& run) {
  const std::optional<std::string> name = run.output     ? run.output
                                          : scene.output ? std::optional(scene.output->name)
                                                         : std::nullopt;
  if (!name) return false;
  const std::optional<DeviceKind> kind = device_kind_for(std::filesystem::path(*name));
  return kind && writes_solids(*kind);
}

}  // namespace

FrameSettings resolve_target(const FrameScene& scene, std::size_t index, const RunSettings& run,
                             const Program& program) {
  FrameSettings s;
  if (scene.cameras.empty() && scene.views.empty() && !run.camera && writes_solids_only(scene, run)) {
    auto own = std::make_shared<NamedCamera>();
    own->name = "solids";
    LookatParameters view;
    view.eye = {1, -1, 1};
    view.target = {0, 0, 0};
    own->camera = lookat_camera(view);
    s.own_camera = own;
    s.camera = own.get();
  } else {
    s.camera = &choose_camera(scene, run.camera, program.main().source->name());
  }
  s.sheet = !scene.views.empty() && !run.camera;
  s.hidden = run.hidden.value_or(scene.hidden.value_or(HiddenStyle::off()));
  // --levels N keeps the script's hidden pen, whose last level's pen must exist: said at the statement.
  if (s.hidden.counts_levels() && scene.hidden_pen && *scene.hidden_pen + s.hidden.levels - 1 > kMaxPen)
    fail(*scene.hidden_span,
         "--levels " + std::to_string(s.hidden.levels) + " from this hidden pen " +
             std::to_string(*scene.hidden_pen) + " needs pens up to " +
             std::to_string(*scene.hidden_pen + s.hidden.levels - 1) + ", past the last pen, " +
             std::to_string(kMaxPen),
         "level k is drawn in pen P + k - 1: fewer levels, or a lower pen in 'style hidden ... pen P'");
  s.target = target_for_frame(run.output, {scene.time.frame, scene.output}, index, program);
  return s;
}

void resolve_device(const FrameScene& scene, const RunSettings& run, FrameSettings& s) {
  s.device = device_for(s.target.device, scene, run);
  PagePlotOptions& plot = s.plot;
  plot.spec = page_spec_for(scene, run.device);
  check_page_spec(plot.spec);
  const DevicePlanning planning = s.device->planning(plot.spec.paper.width_mm, plot.spec.paper.height_mm);
  if (planning.min_margin_mm > plot.spec.margin_mm) {
    plot.spec.margin_mm = planning.min_margin_mm;
    check_page_spec(plot.spec);
  }
  // A plotter draws the caption in single strokes, where its pen reaches: the margin makes room for it.
  plot.caption_as_strokes =
      run.device.decorations && run.device.text_strokes.value_or(planning.text_as_strokes);
  plot.reach_margin_mm = planning.min_margin_mm;
  if (plot.caption_as_strokes && plot.spec.margin_mm < planning.min_margin_mm + kCaptionBandMm) {
    plot.spec.margin_mm = planning.min_margin_mm + kCaptionBandMm;
    check_page_spec(plot.spec);
  }
  s.camera_on_page = framed_camera(s.camera->camera, plot.spec);
  plot.plan.order = run.device.pen_order;
  plot.plan.effort = run.device.plan_effort;
  plot.plan.grid_mm = planning.grid_mm;
  plot.plan.home = planning.home;
  plot.plan.speeds = planning.speeds;
  // The greedy plan a small optimized one must beat is built beside it, as a task of the frame's arena: an
  // idle core takes it, a busy arena runs it in turn (the plan is the same either way).
  plot.plan.threads = 2;
  plot.object_pens = scene.object_pens;
  plot.hatch_pens.clear();
  for (const SceneObject& o : scene.scene.objects) plot.hatch_pens.push_back(o.solid->hatch_pen);
  plot.hidden_pen = scene.hidden_pen;
  plot.hidden = s.hidden;
  if (planning.hidden_as_dashes) plot.hidden_dashes = run.device.dash;  // unset with --dash solid
  if (!s.sheet) s.caption = caption_for(scene, *s.camera, run);         // a sheet has its title block
}

}  // namespace hlr::runtime
