#include "runtime/pipeline/frame_pipeline.hpp"

#include <tbb/global_control.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <map>
#include <memory>
#include <set>
#include <system_error>
#include <thread>
#include <tuple>

#include "core/format_number.hpp"
#include "core/hlr/render_frame.hpp"
#include "core/hlr/view_checks.hpp"
#include "runtime/base/eval_error.hpp"
#include "runtime/base/interrupt.hpp"
#include "runtime/base/limits.hpp"
#include "runtime/pipeline/frame_labels.hpp"
#include "runtime/pipeline/sheet_render.hpp"

namespace hlr::runtime {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// One frame's journey through the pipeline: made by the parallel stage, consumed in order.
struct FrameJob {
  std::size_t index = 0;
  int frame = 0;
  FrameRecord record;
  OutputTarget target;
  std::shared_ptr<const Device> device;
  EncodedFrame encoded;
  std::vector<lang::Diagnostic> warnings;
  std::vector<lang::Diagnostic> view_warnings;  // about this frame's view: said once for all the frames
  std::exception_ptr error;
};

// Warnings about the view (core/hlr/view_checks.hpp), at the camera's statement.
void warn_about_view(const FrameScene& scene, const NamedCamera& named, const Camera& camera,
                     std::vector<lang::Diagnostic>& out) {
  const ViewProblems p = check_view(scene.scene, camera);
  if (p.eye_inside) {
    lang::Diagnostic d;
    d.severity = lang::Severity::Warning;
    d.span = named.span;
    d.message = "camera '" + named.name + "': the eye is inside the closed solid '" +
                scene.scene.objects[*p.eye_inside].name + "', so the drawing shows it from inside";
    d.hint =
        "move the eye out of the solid (or look at it as an open surface, without the faces near the eye)";
    out.push_back(std::move(d));
  }
  if (p.near_plane_cuts_most()) {
    lang::Diagnostic d;
    d.severity = lang::Severity::Warning;
    d.span = named.span;
    d.message = "camera '" + named.name + "': the near plane (depth " +
                format_for_message(camera.near_depth) +
                ") cuts away most of what lies in front of the eye (" + std::to_string(p.vertices_cut_away) +
                " of " + std::to_string(p.vertices_in_front) + " vertices)";
    d.hint = "give the camera a smaller near: depth, or move the eye back";
    out.push_back(std::move(d));
  }
}

// Everything one frame needs, from the script to the bytes for its file.
// The warnings a sheet's page gives: views off the margins or over one another (sheet_warnings), and
// dimensions that could not be drawn.
void sheet_page_warnings(const FrameScene& scene, const PageSpec& spec, const PagePlot& plot, bool framed,
                         std::vector<lang::Diagnostic>& out) {
  for (lang::Diagnostic& d : sheet_warnings(scene, spec, plot.view_boxes, framed))
    out.push_back(std::move(d));
  for (std::size_t i = 0; i < plot.dimension_problems.size() && i < scene.dimensions.size(); ++i)
    if (const std::string& problem = plot.dimension_problems[i]; !problem.empty()) {
      lang::Diagnostic d;
      d.severity = lang::Severity::Warning;
      d.span = scene.dimensions[i].span;
      d.message = "the dimension is not drawn: " + problem;
      d.hint = "measure between points apart in this view, or put it in another view";
      out.push_back(std::move(d));
    }
}

void run_frame(const Program& program, int frame, double fps, const PipelineOptions& options,
               unsigned engine_threads, std::optional<FrameScene>& first, FrameJob& job) {
  const RunSettings& run = options.run;
  FrameScene scene =
      (frame == 0 && first) ? std::move(*first) : program.evaluate(frame_time(frame, run.frame_count, fps));
  job.warnings = std::move(scene.warnings);
  FrameSettings settings = resolve_target(scene, job.index, run, program);
  FrameRecord& r = job.record;
  r.time = scene.time;
  r.evaluate_seconds = scene.evaluate_seconds;
  r.camera_name = settings.camera->name;
  r.hidden = settings.hidden;
  r.path = settings.target.path;
  for (const SceneObject& o : scene.scene.objects) {
    r.object_names.push_back(o.name);
    r.faces += o.solid->faces.size();
  }
  job.target = settings.target;
  if (!options.render) return;

  HlrOptions hlr;
  hlr.include_hidden = settings.hidden.drawn();
  hlr.max_level = settings.hidden.max_level();  // by level: the engine counts the surfaces in front
  hlr.threads = engine_threads;
  hlr.cancel = &interrupt_requested();
  hlr.deadline = scene.deadline;
  const Limits& limits = program.limits();
  const auto out_of_time = [&](const char* stage) {
    fail(settings.camera->span, frame_timeout_message(limits.frame_timeout_s) + " in " + stage,
         "--frame-timeout SECONDS gives each frame more time; a simpler view or scene needs less");
  };
  try {
    resolve_device(scene, run, settings);
  } catch (const DeviceError& e) {  // a page the plotter does not take: at the output statement
    throw OutputError(e.what(), settings.target);
  }
  job.device = settings.device;
  settings.plot.texts = page_labels(scene.labels);

  const Camera& camera = settings.camera_on_page;
  // A mesh file holds the solids themselves (DeviceFrame::scene): no hidden lines to find for it.
  const bool solids_only = writes_solids(settings.target.device);
  const auto render = [&](const Scene& drawn, FrameResult& result) {
    if (solids_only) return;
    try {
      result = render_frame(drawn, camera, hlr);
    } catch (const FrameTimedOut&) {
      out_of_time("the hidden lines");
    }
  };
  const auto start = Clock::now();
  FrameResult result;
  std::optional<SheetDrawing> sheet;
  if (scene.views.empty() && !scene.dimensions.empty())
    fail(scene.dimensions.front().span,
         "a dimension is drawn in a view of a sheet, and this script has no views",
         "place the camera on the sheet: view front = CAMERA at page (X, Y), then 'dimension ... in front'");
  if (settings.sheet) {
    settings.plot.dimensions = sheet_dimensions(scene);
    // Labels at world points belong to one camera's picture; a sheet has several.
    for (const LabelSetting& label : scene.labels)
      if (!label.on_page)
        fail(label.span, "on a sheet of views, a label goes at a page point",
             "write 'label ... at page (X, Y)' in millimetres from the page's top-left corner");
    sheet = render_sheet(
        scene, settings.plot.spec, options.run.device.decorations, settings.hidden, hlr,
        [&](const Scene& drawn, const Camera& view_camera, const HlrOptions& options) {
          FrameResult view;
          if (solids_only) return view;
          try {
            view = render_frame(drawn, view_camera, options);
          } catch (const FrameTimedOut&) {
            out_of_time("the hidden lines");
          }
          return view;
        },
        settings.plot.dimensions);
    result.segments = std::move(sheet->segments);
    result.stats = sheet->stats;
    settings.plot.object_pens.resize(scene.scene.objects.size(), 1);
    settings.plot.hatch_pens.resize(scene.scene.objects.size(), 0);
    for (std::size_t i = 0; i < sheet->shown_names.size(); ++i) {
      r.object_names.push_back(sheet->shown_names[i]);
      settings.plot.object_pens.push_back(sheet->shown_pens[i]);
      settings.plot.hatch_pens.push_back(sheet->shown_hatch_pens[i]);
    }
    settings.hidden = settings.plot.hidden = r.hidden = sheet->hidden;
  } else if (!has_world_labels(scene.labels)) {
    render(scene.scene, result);
  } else {
    // Labels are sized on the page, so the layout comes first: the camera's frame, or (fitting the
    // drawing) the solids' own pieces, found by a first run; the labels then go through the engine with
    // the solids.
    std::optional<Rect2> extent = camera.frame;
    if (!extent) {
      render(scene.scene, result);
      extent = with_label_boxes(drawing_extent(std::nullopt, result.segments), scene.labels, camera,
                                settings.plot.spec);
    }
    Scene labelled = scene.scene;  // the solids are shared, not copied
    settings.plot.object_pens.resize(labelled.objects.size(), 1);
    add_world_labels(scene.labels, camera, fit_rect_to_page(*extent, settings.plot.spec), labelled,
                     settings.plot.object_pens);
    for (std::size_t i = scene.scene.objects.size(); i < labelled.objects.size(); ++i)
      r.object_names.push_back(labelled.objects[i].name);
    render(labelled, result);
    settings.plot.extent = extent;
  }
  r.render_seconds = seconds_since(start);
  // A mesh file draws no page: nothing to warn about how the views look.
  if (!solids_only) {
    if (settings.sheet)
      for (const ViewSetting& v : scene.views)
        warn_about_view(scene, v.camera, v.camera.camera, job.view_warnings);
    else
      warn_about_view(scene, *settings.camera, camera, job.view_warnings);
  }
  // Each piece costs the plan and the device more than the engine: a runaway count stops here.
  if (result.segments.size() > limits.segments)
    fail(settings.camera->span,
         limit_message("visible pieces in one frame", limits.segments, "segments") + ": this view has " +
             std::to_string(result.segments.size()),
         "draw fewer or coarser solids, or look from farther away");
  r.segments = result.segments.size();
  r.stats = result.stats;

  DeviceFrame frame_out;
  frame_out.frame = scene.time.frame;
  frame_out.time = scene.time.time;
  frame_out.camera = &settings.camera_on_page;
  frame_out.segments = &result.segments;
  frame_out.object_names = &r.object_names;
  frame_out.hidden = settings.hidden;
  frame_out.scene = &scene.scene;
  if (sheet) {
    SheetTitle title;
    title.framed = options.run.device.decorations;
    title.title = scene.paper && scene.paper->title ? *scene.paper->title
                                                    : fs::path(options.run.title).filename().string();
    title.scale = sheet->scale_text;
    frame_out.plot = plot_sheet(result.segments, sheet->views, title, settings.plot);
    frame_out.views = &sheet->views;
    if (!solids_only)
      sheet_page_warnings(scene, settings.plot.spec, frame_out.plot, title.framed, job.view_warnings);
  } else {
    frame_out.plot = plot_page(result.segments, camera.frame, settings.caption, settings.plot);
  }
  if (Clock::now() > scene.deadline) out_of_time("the pen plan");
  r.plan = frame_out.plot.stats;
  r.visible_segments = frame_out.plot.visible_segments;
  r.level_pieces = frame_out.plot.level_pieces;
  if (options.write) {
    try {
      const auto encode_start = Clock::now();
      job.encoded = settings.device->encode(frame_out);
      r.encode_seconds = seconds_since(encode_start);
      r.encoded_bytes = job.encoded.size();
    } catch (const DeviceError& e) {
      throw OutputError("cannot write '" + settings.target.path.string() + "': " + e.what(), settings.target);
    }
  }
  if (options.keep_segments) r.kept_segments = std::move(result.segments);
}

// A file being written beside its target, renamed into place by commit(); removed if never committed.
class StagedFile {
 public:
  StagedFile(OutputTarget target, const Device& device) : target_(std::move(target)) {
    try {
      check_writable(target_);
    } catch (const DeviceError& e) {
      throw OutputError(e.what(), target_);
    }
    temp_ = temporary_path_for(target_.path);
    try {
      file_ = device.open(temp_);
    } catch (const DeviceError& e) {
      remove();
      throw OutputError("cannot write '" + target_.path.string() + "': " + e.what(), target_);
    }
  }
  ~StagedFile() { remove(); }
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  bool finished() const { return !file_; }

  void append(EncodedFrame frame) {
    guard([&] { file_->append(std::move(frame)); });
  }
  void finish() {
    guard([&] { file_->finish(); });
    file_.reset();
  }
  void commit() {
    std::error_code ec;
    fs::rename(temp_, target_.path, ec);
    if (ec) throw OutputError("cannot write '" + target_.path.string() + "': " + ec.message(), target_);
    committed_ = true;
  }

 private:
  template <typename F>
  void guard(F&& f) {
    try {
      f();
    } catch (const std::exception& e) {
      throw OutputError("cannot write '" + target_.path.string() + "': " + e.what(), target_);
    }
  }
  void remove() {
    if (committed_) return;
    file_.reset();
    std::error_code ec;
    fs::remove(temp_, ec);
  }

  OutputTarget target_;
  fs::path temp_;
  std::unique_ptr<DeviceFile> file_;
  bool committed_ = false;
};

// The in-order end of the pipeline: results in frame order, files opened and appended to.
class FrameSink {
 public:
  FrameSink(const PipelineOptions& options, std::size_t total) : options_(options), total_(total) {}

  // False once later frames cannot matter: a frame failed (without keep_going), a file could not be
  // written, or the run was interrupted.
  bool take(FrameJob& job) {
    if (stopped_ || interrupted_) return false;
    if (job.error) {
      try {
        std::rethrow_exception(job.error);
      } catch (const RenderCancelled&) {
        interrupted_ = true;
        return false;
      } catch (...) {
      }
      return failed(job, job.error);
    }
    try {
      add(job);
    } catch (const OutputError&) {
      // The disk is full or the folder went away: every later frame would fail the same way.
      failed(job, std::current_exception());
      stopped_ = true;
      return false;
    } catch (...) {
      return failed(job, std::current_exception());
    }
    return true;
  }

  void interrupt() { interrupted_ = true; }

  PipelineResult finish() {
    if (!failures_.empty()) keep_whole_files_and_throw();
    if (interrupted_) keep_complete_files();
    for (std::size_t i = 0; i < files_.size(); ++i) {
      try {
        if (!files_[i]->finished()) files_[i]->finish();
      } catch (const OutputError&) {  // the last bytes of a PDF did not fit on the disk
        broken_.insert(i);
        failures_.push_back({first_frames_[i], std::current_exception()});
        failed_targets_.insert(result_.files[i]);
      }
    }
    if (!failures_.empty()) keep_whole_files_and_throw();
    for (const auto& f : files_) f->commit();
    // Each view warning once, with the frames it holds for (frames arrive in order).
    for (const std::string& key : view_order_) {
      ViewWarning& v = view_warnings_[key];
      const bool run = v.last - v.first + 1 == v.frames;
      v.warning.message += v.frames == 1 ? " (frame " + std::to_string(v.first) + ")"
                           : run
                               ? " (frames " + std::to_string(v.first) + " to " + std::to_string(v.last) + ")"
                               : " (" + std::to_string(v.frames) + " frames, from frame " +
                                     std::to_string(v.first) + " to " + std::to_string(v.last) + ")";
      result_.warnings.push_back(std::move(v.warning));
    }
    return std::move(result_);
  }

 private:
  // Records a failed frame and the file it would have gone to, when that is known. True: go on.
  bool failed(const FrameJob& job, std::exception_ptr error) {
    failures_.push_back({job.frame, error});
    if (!job.target.path.empty())
      failed_targets_.insert(job.target.path);
    else if (const std::optional<std::string>& pattern = options_.run.output)
      failed_targets_.insert(has_frame_field(*pattern) ? substitute_frame(*pattern, job.frame) : *pattern);
    else
      unknown_target_ = true;
    if (!options_.keep_going) stopped_ = true;  // frames after it, already in flight, are dropped
    return !stopped_;
  }

  // After failures: a file is kept when it is whole — a one-frame file that was written, or a file of
  // several frames that no failed frame (nor an interruption) could have gone to.
  [[noreturn]] void keep_whole_files_and_throw() {
    std::vector<fs::path> kept;
    std::vector<bool> keep(files_.size(), false);
    // A failed frame whose file is unknown (the script's output name is evaluated with the frame) went
    // to a file of its own when every frame so far did: the names vary per frame.
    const bool per_frame_names = result_.files.size() >= 2 && result_.files.size() == done_.size();
    for (std::size_t i = 0; i < files_.size(); ++i) {
      StagedFile& file = *files_[i];
      if (broken_.count(i)) continue;
      const bool last = i + 1 == files_.size();
      keep[i] = file.finished() || ((!unknown_target_ || per_frame_names) &&
                                    !failed_targets_.count(result_.files[i]) && !(interrupted_ && last));
      if (!keep[i]) continue;
      try {
        if (!file.finished()) file.finish();
        file.commit();
        kept.push_back(result_.files[i]);
      } catch (...) {
        keep[i] = false;
      }
    }
    files_.clear();  // removes every file not committed
    std::vector<int> done;
    for (std::size_t k = 0; k < done_.size(); ++k)
      if (!options_.write || !options_.render || keep[done_file_[k]]) done.push_back(done_[k]);
    std::sort(
        failures_.begin(), failures_.end(),
        [](const FramesFailed::Failure& a, const FramesFailed::Failure& b) { return a.frame < b.frame; });
    if (failures_.size() == 1 && kept.empty()) std::rethrow_exception(failures_.front().error);
    throw FramesFailed(std::move(failures_), std::move(done), std::move(kept));
  }

  // Frames are taken in order and a file's frames are consecutive, so every file but the one the last
  // frame went to is whole; that one too when its device holds one frame.
  [[noreturn]] void keep_complete_files() {
    std::vector<fs::path> kept;
    bool removed = false;
    for (std::size_t i = 0; i < files_.size(); ++i) {
      const bool last = i + 1 == files_.size();
      if (last && !files_[i]->finished()) {
        removed = true;
        continue;
      }
      if (!files_[i]->finished()) files_[i]->finish();
      files_[i]->commit();
      kept.push_back(result_.files[i]);
    }
    files_.clear();  // removes the file that was still being written
    // Done: the frames that are in a kept file (without files, every frame taken).
    std::vector<int> done;
    for (std::size_t k = 0; k < done_.size(); ++k)
      if (!removed || done_file_[k] + 1 != result_.files.size()) done.push_back(done_[k]);
    throw RunInterrupted(std::move(done), std::move(kept), removed);
  }

  void add(FrameJob& job) {
    const int frame = job.record.time.frame;
    const bool writing = options_.write && options_.render;
    const auto found = by_path_.find(job.target.path);
    std::size_t index = 0;
    if (found == by_path_.end()) {
      // Opened before it is registered: a file that cannot be created leaves no trace in the result.
      std::unique_ptr<StagedFile> staged =
          writing ? std::make_unique<StagedFile>(job.target, *job.device) : nullptr;
      index = result_.files.size();
      by_path_.emplace(job.target.path, index);
      result_.files.push_back(job.target.path);
      first_frames_.push_back(frame);
      if (staged) files_.push_back(std::move(staged));
    } else {
      index = found->second;
      if (one_frame_per_file(job.target.device))
        fail_several_frames(job.target, first_frames_[index], frame, options_.run.output.has_value());
    }
    if (writing) {
      StagedFile& file = *files_[index];
      try {
        file.append(std::move(job.encoded));
        // A one-frame file is complete now: closed at once, so a 10 000-frame sequence holds no open
        // files, only the names to rename at the end.
        if (one_frame_per_file(job.target.device)) file.finish();
      } catch (...) {
        broken_.insert(index);
        throw;
      }
    }
    for (lang::Diagnostic& w : job.warnings)
      if (seen_.emplace(w.span.file, w.span.begin, w.span.end, w.message).second)
        result_.warnings.push_back(std::move(w));
    for (lang::Diagnostic& w : job.view_warnings) {
      ViewWarning& v = view_warnings_[w.message];
      if (v.frames++ == 0) {
        v.first = frame;
        v.warning = std::move(w);
        view_order_.push_back(v.warning.message);
      }
      v.last = frame;
    }
    ++result_.frame_count;
    done_.push_back(frame);
    done_file_.push_back(index);
    if (options_.on_frame) options_.on_frame(result_.frame_count, total_);
    result_.faces += job.record.faces;
    result_.segments += job.record.segments;
    if (options_.keep_records) result_.frames.push_back(std::move(job.record));
  }

  const PipelineOptions& options_;
  PipelineResult result_;
  std::map<fs::path, std::size_t> by_path_;
  std::vector<std::unique_ptr<StagedFile>> files_;
  std::vector<int> first_frames_;
  std::set<std::tuple<lang::FileId, std::uint32_t, std::uint32_t, std::string>> seen_;
  struct ViewWarning {
    lang::Diagnostic warning;
    int first = 0, last = 0, frames = 0;
  };
  std::map<std::string, ViewWarning> view_warnings_;  // by message
  std::vector<std::string> view_order_;               // the messages in the order first met
  std::vector<FramesFailed::Failure> failures_;
  std::set<fs::path> failed_targets_;  // files a failed frame went to, where known
  bool unknown_target_ = false;        // a failed frame whose file is not known
  std::set<std::size_t> broken_;       // files an append or finish failed on
  bool stopped_ = false;               // a frame failed (without keep_going) or a file could not be written
  std::atomic<bool> interrupted_{false};  // also set by the input stage, on another thread
  std::vector<int> done_;                 // frames taken, in order
  std::vector<std::size_t> done_file_;    // the file each went to (an index into result_.files)
  std::size_t total_;                     // frames asked for
};

}  // namespace

PipelineResult run_pipeline(const Program& program, const std::vector<int>& frames, double fps,
                            const PipelineOptions& options, std::optional<FrameScene> first) {
  const unsigned hardware = std::max(1U, std::thread::hardware_concurrency());
  const unsigned jobs = options.jobs == 0 ? hardware : options.jobs;
  // Frames in flight: enough to keep every thread busy while one waits its turn to be written, few
  // enough that memory does not grow with the sequence.
  const std::size_t tokens = 2 * static_cast<std::size_t>(jobs) + 1;
  FrameSink sink(options, frames.size());
  std::size_t next = 0;
  std::atomic<bool> stop{false};

  auto input = [&](tbb::flow_control& fc) -> FrameJob* {
    if (interrupt_requested()) sink.interrupt();
    if (stop || interrupt_requested() || next >= frames.size()) {
      fc.stop();
      return nullptr;
    }
    auto* job = new FrameJob;
    job->index = next++;
    job->frame = frames[job->index];
    return job;
  };
  auto work = [&](FrameJob* job) -> FrameJob* {
    const int frame = frames[job->index];
    try {
      run_frame(program, frame, fps, options, jobs == 1 ? 1 : 0, first, *job);
    } catch (EvalError& e) {
      if (options.run.frame_count > 1 && !e.diagnostics.empty())
        e.diagnostics.front().message += " (in frame " + std::to_string(frame) + ")";
      job->error = std::current_exception();
    } catch (...) {
      job->error = std::current_exception();
    }
    return job;
  };
  auto output = [&](FrameJob* job) {
    const std::unique_ptr<FrameJob> owned(job);
    if (!sink.take(*job)) stop = true;
  };

  if (jobs == 1) {  // no scheduler at all: one frame after another on this thread
    for (FrameJob* job; !stop && next < frames.size();) {
      if (interrupt_requested()) {
        sink.interrupt();
        break;
      }
      job = new FrameJob;
      job->index = next++;
      job->frame = frames[job->index];
      output(work(job));
    }
    return sink.finish();
  }
  // Worker threads get the stack a main thread has (glibc's 8 MiB), not oneTBB's smaller default: the
  // engine and the planner run on them as they would on the caller's thread.
  const tbb::global_control stack(tbb::global_control::thread_stack_size, std::size_t{8} << 20);
  auto run_all = [&] {
    if (frames.size() == 1) {  // the frame's own work (objects, edges) is what runs in parallel
      auto* job = new FrameJob;
      job->frame = frames[0];
      output(work(job));
      return;
    }
    tbb::parallel_pipeline(tokens,
                           tbb::make_filter<void, FrameJob*>(tbb::filter_mode::serial_in_order, input) &
                               tbb::make_filter<FrameJob*, FrameJob*>(tbb::filter_mode::parallel, work) &
                               tbb::make_filter<FrameJob*, void>(tbb::filter_mode::serial_in_order, output));
  };
  // Every core: TBB's own arena, started only when work is shared out (a small frame never starts it).
  if (jobs == hardware) {
    run_all();
  } else {
    tbb::task_arena arena(static_cast<int>(jobs));
    arena.execute(run_all);
  }
  return sink.finish();
}

}  // namespace hlr::runtime
