// One run of a script: load → evaluate frame 0 (animation length, output names, camera) → select frames
// → evaluate and render them → write every output atomically (a failed frame keeps only whole files:
// frame_pipeline.hpp) → report. Errors become exit statuses here.
#include "runtime/pipeline/script_run.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iterator>
#include <ostream>

#include "core/device/page/atomic_file.hpp"
#include "core/device/page/device.hpp"
#include "core/hlr/render_frame.hpp"
#include "runtime/base/eval_error.hpp"
#include "runtime/base/file_access.hpp"
#include "runtime/pipeline/frame_pipeline.hpp"
#include "runtime/pipeline/output_plan.hpp"
#include "runtime/pipeline/progress_line.hpp"

namespace hlr::runtime {

namespace {

using Clock = std::chrono::steady_clock;

bool leave_at_exit = false;
const Program* left_at_exit = nullptr;  // reachable to the end, not a leak

int report(std::ostream& err, const EvalError& e, const Program* program) {
  if (e.diagnostics.empty() || !program) {
    err << "hlrscript: error: " << e.what() << "\n";
  } else {
    print_diagnostics(err, e.diagnostics, program->sources());
  }
  switch (e.kind) {
    case ErrorKind::Input:
      return kExitInput;
    case ErrorKind::Denied:
      return kExitDenied;
    case ErrorKind::Script:
      break;
  }
  return kExitScript;
}

// A device failure; at the script's `output` statement when the name came from there.
int report(std::ostream& err, const OutputError& e, const Program& program) {
  if (!e.target.span) {
    err << "hlrscript: error: " << e.what() << "\n";
  } else {
    lang::Diagnostic d;
    d.span = *e.target.span;
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

// "0-11,14,20-23": frame numbers in increasing order as --frames takes them.
std::string frame_list_text(const std::vector<int>& frames) {
  std::string out;
  for (std::size_t i = 0; i < frames.size();) {
    std::size_t j = i;
    while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
    out += (out.empty() ? "" : ",") + std::to_string(frames[i]) +
           (j > i ? "-" + std::to_string(frames[j]) : std::string());
    i = j + 1;
  }
  return out;
}

int report(std::ostream& err, const RunInterrupted& e, const std::vector<int>& asked) {
  std::vector<int> rest;
  std::set_difference(asked.begin(), asked.end(), e.frames_done.begin(), e.frames_done.end(),
                      std::back_inserter(rest));
  err << "hlrscript: interrupted after " << e.frames_done.size() << " of " << asked.size() << " frames"
      << (e.frames_done.empty() ? "" : " (" + frame_list_text(e.frames_done) + ")") << "; kept "
      << e.files.size() << (e.files.size() == 1 ? " complete file" : " complete files")
      << (e.removed_partial ? ", removed the one still being written" : "") << "\n";
  if (!rest.empty()) err << "hint: --frames " << frame_list_text(rest) << " renders the rest\n";
  return kExitInterrupted;
}

// Each failed frame's own error, then what was kept: "frames 7 and 30 of 48 failed; kept 46 complete
// files (0-6,8-29,31-47)". The status is the first failure's.
int report(std::ostream& err, const FramesFailed& e, const std::vector<int>& asked, const Program& program) {
  int code = kExitInternal;
  std::vector<int> failed;
  for (const FramesFailed::Failure& f : e.failures) {
    failed.push_back(f.frame);
    int c = kExitInternal;
    try {
      std::rethrow_exception(f.error);
    } catch (const EvalError& x) {
      c = report(err, x, &program);
    } catch (const RunError& x) {
      c = report(err, x);
    } catch (const OutputError& x) {
      c = report(err, x, program);
    } catch (const std::exception& x) {
      err << "hlrscript: internal error in frame " << f.frame << ": " << x.what() << "\n";
    }
    if (code == kExitInternal) code = c;
  }
  err << "hlrscript: " << (failed.size() == 1 ? "frame " : "frames ") << frame_list_text(failed) << " of "
      << asked.size() << " failed; kept " << e.files.size()
      << (e.files.size() == 1 ? " complete file" : " complete files")
      << (e.frames_done.empty() ? "" : " (frames " + frame_list_text(e.frames_done) + ")")
      << ", none partial\n";
  std::vector<int> rest;
  std::set_difference(asked.begin(), asked.end(), e.frames_done.begin(), e.frames_done.end(),
                      std::back_inserter(rest));
  if (!rest.empty()) err << "hint: once fixed, --frames " << frame_list_text(rest) << " renders the rest\n";
  return code;
}

void print_stats(std::ostream& err, const PipelineResult& result) {
  for (const FrameRecord& f : result.frames) {
    char line[320];
    std::snprintf(
        line, sizeof line,
        "frame %d: camera %s, %zu objects, %zu faces, %zu segments (%zu candidate edges, %zu occluders, "
        "%zu face tests, %zu intersection pieces), evaluate %.2f ms, hidden-line %.2f ms\n",
        f.time.frame, f.camera_name.c_str(), f.object_names.size(), f.faces, f.segments,
        f.stats.candidate_edges, f.stats.occluder_faces, f.stats.face_tests, f.stats.intersection_lines,
        f.evaluate_seconds * 1e3, f.render_seconds * 1e3);
    err << line;
    const FrameStats::Stages& ms = f.stats.ms;
    std::snprintf(line, sizeof line,
                  "frame %d hidden-line stages: self-crossing search %.2f ms, setup %.2f ms, grid %.2f ms, "
                  "examine %.2f ms, intersection lines and join %.2f ms\n",
                  f.time.frame, ms.self_crossings, ms.setup, ms.grid, ms.examine, ms.finish);
    err << line;
  }
  // Pen plans file by file, as the files were written.
  for (const std::filesystem::path& file : result.files)
    for (const FrameRecord& f : result.frames) {
      if (f.path != file) continue;
      const PlanStats& s = f.plan;
      char dashes[96] = "";
      if (s.hidden_dashes > 0)
        std::snprintf(dashes, sizeof dashes, " before the hidden lines were cut into %zu dashes",
                      s.hidden_dashes);
      char line[768];
      std::snprintf(
          line, sizeof line,
          "frame %d -> %s: %zu visible pieces (%zu drawing-graph edges after snapping, merging, splitting); "
          "pen-down %.1f mm, pen-up %.1f mm "
          "(mean %.1f, median %.1f), %zu lifts (lower bound %zu%s), plotting ~%.1f s, planned in %.2f ms, "
          "encoded in %.2f ms (%zu bytes)\n",
          f.time.frame, file.filename().string().c_str(), f.visible_segments, s.merged_pieces, s.pen_down_mm,
          s.pen_up_mm, s.pen_up_mean_mm, s.pen_up_median_mm, s.lifts, s.lift_lower_bound, dashes,
          s.plot_seconds, s.planning_ms, f.encode_seconds * 1e3, f.encoded_bytes);
      err << line;
      if (f.level_pieces.size() > 1) {  // drawn by occlusion level
        err << "frame " << f.time.frame << " hidden pieces by level:";
        for (std::size_t k = 1; k < f.level_pieces.size(); ++k)
          err << (k > 1 ? ", " : " ") << k << ": " << f.level_pieces[k];
        err << "\n";
      }
    }
}

std::string join_cameras(const FrameScene& scene) {
  std::string out;
  for (const NamedCamera& c : scene.cameras) out += (out.empty() ? "" : ", ") + c.name;
  return out;
}

// SOURCE_DATE_EPOCH (reproducible-builds.org) fixes the PDF's creation date, so that a rerun gives the
// same bytes; otherwise cairo writes the current time.
std::string creation_date_from_environment() {
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  if (!epoch || !*epoch) return "";
  char* end = nullptr;
  const long long seconds = std::strtoll(epoch, &end, 10);
  if (*end != '\0' || seconds < 0) return "";
  const std::time_t t = static_cast<std::time_t>(seconds);
  std::tm tm{};
  if (!gmtime_r(&t, &tm)) return "";
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace

// Load → evaluate frame 0 (animation length, camera, output name) → select frames → the frame pipeline
// (runtime/pipeline/frame_pipeline.hpp) → report.
int run_loaded_program(const Program& program, const RunOptions& o, std::ostream& out, std::ostream& err,
                       Program* releasable, Clock::time_point start) {
  const std::string& name = program.main().source->name();
  ProgressLine progress(err, o.progress);
  std::vector<int> asked;  // the frames selected, once known
  try {
    FrameScene first = program.evaluate_first_frame();
    if (o.list_cameras) {
      for (const NamedCamera& c : first.cameras) out << c.name << "\n";
      return kExitOk;
    }
    const int frame_count = first.animation ? first.animation->frames : 1;
    const double fps = first.animation ? first.animation->fps : kDefaultFps;
    const std::vector<int> frames = select_frames(frame_count, o.frames, o.shard);
    asked = frames;

    PipelineOptions options;
    options.run.title = o.title.value_or(name);
    options.run.frame_count = frame_count;
    options.run.camera = o.camera;
    options.run.hidden = o.hidden;
    options.run.output = o.output;
    options.run.device = o.device;
    options.run.device.creation_date = creation_date_from_environment();
    options.jobs = o.jobs;
    options.render = !o.check;
    options.keep_records = o.stats;  // a long sequence keeps no per-frame record unless asked
    options.keep_going = o.keep_going;
    options.on_frame = [&](std::size_t done, std::size_t total) { progress.update(done, total); };

    // Mistakes visible in frame 0 are reported before any rendering: no camera, a bad output name, a
    // missing directory, one file named for several frames of a one-frame device.
    const FrameSettings settings0 = resolve_target(first, 0, options.run, program);
    if (o.output && !has_frame_field(*o.output) && frames.size() > 1 &&
        one_frame_per_file(settings0.target.device))
      fail_several_frames(settings0.target, frames[0], frames[1], true);
    try {
      check_writable(settings0.target);
    } catch (const DeviceError& e) {
      return report(err, OutputError(e.what(), settings0.target), program);
    }
    if (o.shard && o.shard->count > 1 && o.output && !has_frame_field(*o.output))
      err << "hlrscript: warning: every shard writes '" << *o.output
          << "'; put {frame:04} in the name to keep the shards' frames apart\n";
    if (frames.empty()) {
      out << name << ": --shard " << o.shard->index << "/" << o.shard->count << " selects none of its "
          << frame_count << " frames; nothing to do\n";
      return kExitOk;
    }
    const std::string cameras = join_cameras(first);
    const std::size_t objects = first.scene.objects.size();
    // Only a render gains from the release (the engine's memory); `check` would spend time on it.
    if (releasable && options.render && frames.size() == 1 && frames[0] == 0) releasable->release_syntax();

    const PipelineResult result = run_pipeline(program, frames, fps, options, std::move(first));
    progress.clear();
    std::vector<lang::Diagnostic> shown;
    std::size_t notes = 0;
    for (const lang::Diagnostic& w : result.warnings)
      if (w.severity != lang::Severity::Note || o.verbose)
        shown.push_back(w);
      else
        ++notes;
    print_diagnostics(err, shown, program.sources());
    if (o.stats && options.render) print_stats(err, result);

    const std::size_t faces = result.faces, segments = result.segments;
    const std::string files =
        result.files.front().string() +
        (result.files.size() > 1 ? " and " + std::to_string(result.files.size() - 1) + " more files" : "");
    if (o.check) {
      out << name << ": ok: " << result.frame_count << (result.frame_count == 1 ? " frame" : " frames")
          << " evaluated, " << objects << " objects in frame 0, " << faces
          << " faces drawn in all, cameras: " << cameras << "; would write " << files << "\n";
      return kExitOk;
    }
    // A mesh file holds the solids' faces, not the drawing's segments.
    const std::optional<DeviceKind> kind = device_kind_for(result.files.front());
    const bool mesh = kind && writes_solids(*kind);
    char line[256];
    std::snprintf(line, sizeof line, ": %zu %s, %zu %s in %.2f s\n", result.frame_count,
                  result.frame_count == 1 ? "frame" : "frames", mesh ? faces : segments,
                  mesh ? "faces" : "segments", std::chrono::duration<double>(Clock::now() - start).count());
    out << "wrote " << files << line;
    if (notes > 0)
      err << "hlrscript: " << notes << (notes == 1 ? " note" : " notes")
          << " on what the script's solid options accept (--verbose shows them)\n";
    return kExitOk;
  } catch (const EvalError& e) {
    return report(err, e, &program);
  } catch (const RunError& e) {
    return report(err, e);
  } catch (const OutputError& e) {
    return report(err, e, program);
  } catch (const FramesFailed& e) {
    progress.clear();
    return report(err, e, asked, program);
  } catch (const RunInterrupted& e) {
    progress.clear();
    return report(err, e, asked);
  } catch (const RenderCancelled&) {
    if (o.from_repl) throw;  // the REPL says it stopped
    progress.clear();
    err << "hlrscript: interrupted before any frame was written; nothing written\n";
    return kExitInterrupted;
  }
}

int run_script(const RunOptions& o, std::ostream& out, std::ostream& err,
               std::vector<std::filesystem::path>* inputs) {
  const auto start = Clock::now();
  std::unique_ptr<Program> program;
  try {
    program = Program::load(o.script, o.script, o.access);
    program->set_limits(o.limits);
  } catch (const EvalError& e) {
    err << "hlrscript: error: " << e.what() << "\n";
    return kExitInput;
  }
  int code = kExitScript;
  if (!program->parsed())
    print_diagnostics(err, program->syntax_errors(), program->sources());
  else
    code = run_loaded_program(*program, o, out, err, program.get(), start);
  if (inputs) *inputs = program->sources().paths();
  if (leave_at_exit && !inputs && !left_at_exit) left_at_exit = program.release();
  return code;
}

void leave_program_at_exit() { leave_at_exit = true; }

}  // namespace hlr::runtime
