// The hlrscript command: load → evaluate frame 0 (animation length, output names, camera) → select frames
// → evaluate and render them → write every output atomically. Nothing is written unless every frame
// succeeded. Errors become exit statuses here and nowhere else.
#include "runtime/cli.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ostream>
#include <thread>

#include "core/device/atomic_file.hpp"
#include "core/device/cairo_device.hpp"
#include "core/device/page_plot.hpp"
#include "runtime/demo_scene.hpp"
#include "runtime/eval_error.hpp"
#include "runtime/frame_runner.hpp"
#include "runtime/output_plan.hpp"
#include "runtime/program.hpp"

namespace hlr::runtime {

namespace {

constexpr const char* kVersion = "hlrscript 0.1.0";

int report(std::ostream& err, const EvalError& e, const Program* program) {
  if (e.diagnostics.empty() || !program) {
    err << "hlrscript: error: " << e.what() << "\n";
  } else {
    print_diagnostics(err, e.diagnostics, program->sources());
  }
  return e.kind == ErrorKind::Input ? kExitInput : kExitScript;
}

// A device failure; at the script's `output` statement when the name came from there.
int report(std::ostream& err, const DeviceError& e, const OutputTarget& target, const Program& program) {
  if (!target.span) {
    err << "hlrscript: error: " << e.what() << "\n";
  } else {
    lang::Diagnostic d;
    d.span = *target.span;
    d.message = e.what();
    print_diagnostics(err, {d}, program.sources());
  }
  return kExitOutput;
}

int report(std::ostream& err, const RunError& e) {
  err << "hlrscript: error: " << e.what() << "\n";
  if (!e.hint.empty()) err << "hint: " << e.hint << "\n";
  return e.exit_code;
}

int run_demo(const CliOptions& o, std::ostream& out, std::ostream& err) {
  const std::string target = o.output.value_or("carrier.pdf");
  if (device_for(target) != Device::Pdf) {
    err << "hlrscript: error: '" << target << "': the demo writes PDF only; name the output *.pdf\n";
    return kExitUsage;
  }
  HlrOptions options;
  options.include_hidden = o.hidden.value_or(false);
  DemoStats stats;
  const auto drawings = render_carrier_demo(o.demo_frames, options, stats);
  PagePlotOptions plot;
  plot.include_hidden = options.include_hidden;
  plot.plan.order = o.device.pen_order;
  std::vector<PlotPage> pages;
  for (const DrawingPage& d : drawings) pages.push_back(plot_page(d.segments, d.frame, d.caption, plot).page);
  CairoOptions pdf;
  pdf.format = CairoFormat::Pdf;
  pdf.title = "hlrscript demo: Desens' carrier";
  write_cairo(target, pages, pdf);
  char line[256];
  std::snprintf(line, sizeof line,
                "wrote %s: %zu pages, %zu segments, hidden-line time %.1f ms (%.2f ms per frame)\n",
                target.c_str(), stats.frames, stats.segments, stats.seconds * 1e3,
                stats.seconds * 1e3 / static_cast<double>(stats.frames));
  out << line;
  return kExitOk;
}

void print_plan_stats(std::ostream& err, const OutputTarget& target,
                      const std::vector<WrittenFrame>& written) {
  for (const WrittenFrame& w : written) {
    const PlanStats& s = w.plan;
    char line[640];
    std::snprintf(
        line, sizeof line,
        "frame %d -> %s: %zu visible pieces (%zu drawing-graph edges after snapping, merging, splitting); "
        "pen-down %.1f mm, pen-up %.1f mm "
        "(mean %.1f, median %.1f), %zu lifts (lower bound %zu), plotting ~%.1f s, planned in %.2f ms\n",
        w.frame, target.path.filename().string().c_str(), w.visible_segments, s.merged_pieces, s.pen_down_mm,
        s.pen_up_mm, s.pen_up_mean_mm, s.pen_up_median_mm, s.lifts, s.lift_lower_bound, s.plot_seconds,
        s.planning_ms);
    err << line;
  }
}

void print_stats(std::ostream& err, const std::vector<FrameOutput>& frames) {
  for (const FrameOutput& f : frames) {
    char line[320];
    std::snprintf(
        line, sizeof line,
        "frame %d: camera %s, %zu objects, %zu faces, %zu segments (%zu candidate edges, %zu occluders, "
        "%zu face tests, %zu intersection pieces), evaluate %.2f ms, hidden-line %.2f ms\n",
        f.time.frame, f.camera_name.c_str(), f.object_names.size(), f.faces, f.segments.size(),
        f.stats.candidate_edges, f.stats.occluder_faces, f.stats.face_tests, f.stats.intersection_lines,
        f.evaluate_seconds * 1e3, f.render_seconds * 1e3);
    err << line;
  }
}

std::string join_cameras(const FrameScene& scene) {
  std::string out;
  for (const NamedCamera& c : scene.cameras) out += (out.empty() ? "" : ", ") + c.name;
  return out;
}

int run_script(const CliOptions& o, std::ostream& out, std::ostream& err) {
  std::unique_ptr<Program> program;
  try {
    program = Program::load(o.script, o.script);
  } catch (const EvalError& e) {
    err << "hlrscript: error: " << e.what() << "\n";
    return kExitInput;
  }
  if (!program->parsed()) {
    print_diagnostics(err, program->syntax_errors(), program->sources());
    return kExitScript;
  }

  try {
    FrameScene first = program->evaluate(frame_time(0, 1, 24));
    const int frame_count = first.animation ? first.animation->frames : 1;
    const double fps = first.animation ? first.animation->fps : 24;
    const std::vector<int> frames = select_frames(frame_count, o.frames, o.shard);
    // Mistakes visible in frame 0 are reported before any rendering.
    choose_camera(first, o.camera, o.script);
    if (o.output && !has_frame_field(*o.output)) {
      // A name without {frame} for several frames: refused now for one-frame devices, not after rendering.
      std::vector<FrameName> all;
      for (const int f : frames) all.push_back({f, std::nullopt});
      plan_outputs(o.output, all, *program);
    }
    for (const OutputTarget& t : plan_outputs(o.output, {FrameName{0, first.output}}, *program)) {
      try {
        check_writable(t);
      } catch (const DeviceError& e) {
        return report(err, e, t, *program);
      }
    }
    if (o.shard && o.shard->count > 1 && o.output && !has_frame_field(*o.output))
      err << "hlrscript: warning: every shard writes '" << *o.output
          << "'; put {frame:04} in the name to keep the shards' frames apart\n";
    if (frames.empty()) {
      out << o.script << ": --shard " << o.shard->index << "/" << o.shard->count << " selects none of its "
          << frame_count << " frames; nothing to do\n";
      return kExitOk;
    }
    const std::string cameras = join_cameras(first);
    const std::size_t objects = first.scene.objects.size();

    RunOptions run;
    run.camera = o.camera;
    run.hidden = o.hidden;
    run.jobs = o.jobs == 0 ? std::max(1U, std::thread::hardware_concurrency()) : o.jobs;
    run.render = o.mode == CliOptions::Mode::Render;
    const auto start = std::chrono::steady_clock::now();
    RunResult result = run_frames(*program, frames, frame_count, fps, run, std::move(first));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    print_diagnostics(err, result.warnings, program->sources());

    std::vector<FrameName> names;
    for (const FrameOutput& f : result.frames) names.push_back({f.time.frame, f.output});
    const std::vector<OutputTarget> targets = plan_outputs(o.output, names, *program);
    if (o.stats && o.mode == CliOptions::Mode::Render) print_stats(err, result.frames);

    std::size_t faces = 0, segments = 0;
    for (const FrameOutput& f : result.frames) {
      faces += f.faces;
      segments += f.segments.size();
    }
    if (o.mode == CliOptions::Mode::Check) {
      out << o.script << ": ok: " << result.frames.size()
          << (result.frames.size() == 1 ? " frame" : " frames") << " evaluated, " << objects
          << " objects in frame 0, " << faces << " faces drawn in all, cameras: " << cameras
          << "; would write " << targets.front().path.string()
          << (targets.size() > 1 ? " and " + std::to_string(targets.size() - 1) + " more files" : "") << "\n";
      return kExitOk;
    }

    WriteOptions write;
    write.title = o.script;
    write.frame_count = frame_count;
    write.device = o.device;
    for (const OutputTarget& t : targets) {
      try {
        const std::vector<WrittenFrame> written = write_output(t, result.frames, write);
        if (o.stats) print_plan_stats(err, t, written);
      } catch (const DeviceError& e) {
        return report(err, e, t, *program);
      }
    }
    char line[256];
    std::snprintf(line, sizeof line, ": %zu %s, %zu segments in %.2f s\n", result.frames.size(),
                  result.frames.size() == 1 ? "frame" : "frames", segments, seconds);
    out << "wrote " << targets.front().path.string()
        << (targets.size() > 1 ? " and " + std::to_string(targets.size() - 1) + " more files" : "") << line;
    return kExitOk;
  } catch (const EvalError& e) {
    return report(err, e, program.get());
  } catch (const RunError& e) {
    return report(err, e);
  }
}

}  // namespace

int run_cli(int argc, const char* const argv[], std::ostream& out, std::ostream& err) {
  const std::optional<CliOptions> options = parse_cli(argc, argv, err);
  if (!options) return kExitUsage;
  try {
    switch (options->mode) {
      case CliOptions::Mode::Help:
        out << usage_text();
        return kExitOk;
      case CliOptions::Mode::Version:
        out << kVersion << "\n";
        return kExitOk;
      case CliOptions::Mode::Demo:
        return run_demo(*options, out, err);
      case CliOptions::Mode::Render:
      case CliOptions::Mode::Check:
        return run_script(*options, out, err);
    }
  } catch (const DeviceError& e) {
    err << "hlrscript: error: " << e.what() << "\n";
    return kExitOutput;
  } catch (const std::exception& e) {
    err << "hlrscript: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitInternal;
}

}  // namespace hlr::runtime
