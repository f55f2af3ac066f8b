#include "runtime/frame_runner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <map>
#include <thread>
#include <tuple>

#include "core/hlr/render_frame.hpp"
#include "runtime/eval_error.hpp"

namespace hlr::runtime {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string camera_list(const FrameScene& scene) {
  std::string out;
  for (const NamedCamera& c : scene.cameras) out += (out.empty() ? "" : ", ") + c.name;
  return out;
}

FrameOutput render_one(const FrameScene& scene, const std::string& script_name, const RunOptions& options,
                       unsigned engine_threads) {
  const NamedCamera& camera = choose_camera(scene, options.camera, script_name);
  FrameOutput out;
  out.time = scene.time;
  out.camera_name = camera.name;
  out.camera = camera.camera;
  out.output = scene.output;
  out.paper = scene.paper;
  out.object_pens = scene.object_pens;
  out.hidden_pen = scene.hidden_pen;
  out.pens = scene.pens;
  out.plotters = scene.plotters;
  for (const SceneObject& o : scene.scene.objects) {
    out.object_names.push_back(o.name);
    out.faces += o.solid.faces.size();
  }
  if (options.render) {
    HlrOptions hlr;
    hlr.include_hidden = options.hidden.value_or(scene.hidden.value_or(false));
    out.hidden = hlr.include_hidden;
    hlr.threads = engine_threads;
    const auto start = Clock::now();
    FrameResult result = render_frame(scene.scene, camera.camera, hlr);
    out.render_seconds = seconds_since(start);
    out.segments = std::move(result.segments);
    out.stats = result.stats;
  }
  return out;
}

struct Slot {
  std::optional<FrameOutput> output;
  std::vector<lang::Diagnostic> warnings;
  std::exception_ptr error;
};

}  // namespace

const NamedCamera& choose_camera(const FrameScene& scene, const std::optional<std::string>& wanted,
                                 const std::string& script_name) {
  if (scene.cameras.empty())
    throw RunError(script_name + ": the script declares no camera",
                   "add one, for example: camera main = lookat(eye: (30, 20, 15), target: (0, 0, 0))", 65);
  if (!wanted) return scene.cameras.back();
  for (const NamedCamera& c : scene.cameras)
    if (c.name == *wanted) return c;
  throw RunError("--camera " + *wanted + ": " + script_name + " declares no camera named '" + *wanted + "'",
                 "its cameras: " + camera_list(scene), 64);
}

RunResult run_frames(const Program& program, const std::vector<int>& frames, int frame_count, double fps,
                     const RunOptions& options, std::optional<FrameScene> first) {
  const std::string& script_name = program.main().source->name();
  std::vector<Slot> slots(frames.size());
  const unsigned jobs = std::max(1U, std::min<unsigned>(options.jobs, static_cast<unsigned>(frames.size())));
  const unsigned hardware = std::max(1U, std::thread::hardware_concurrency());
  // One frame at a time: the engine uses every core. Several: they share the cores.
  const unsigned engine_threads = jobs == 1 ? 0 : std::max(1U, hardware / jobs);

  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> first_failed{frames.size()};
  auto work = [&] {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= frames.size()) return;
      if (i > first_failed.load()) continue;  // a lower frame failed: this one cannot matter
      Slot& slot = slots[i];
      try {
        FrameScene scene = (frames[i] == 0 && first)
                               ? std::move(*first)
                               : program.evaluate(frame_time(frames[i], frame_count, fps));
        slot.warnings = std::move(scene.warnings);
        slot.output = render_one(scene, script_name, options, engine_threads);
        slot.output->evaluate_seconds = scene.evaluate_seconds;
      } catch (EvalError& e) {
        if (frame_count > 1 && !e.diagnostics.empty())
          e.diagnostics.front().message += " (in frame " + std::to_string(frames[i]) + ")";
        slot.error = std::current_exception();
      } catch (...) {
        slot.error = std::current_exception();
      }
      if (slot.error) {
        std::size_t seen = first_failed.load();
        while (i < seen && !first_failed.compare_exchange_weak(seen, i)) {
        }
      }
    }
  };
  if (jobs == 1) {
    work();
  } else {
    std::vector<std::thread> threads;
    for (unsigned j = 0; j < jobs; ++j) threads.emplace_back(work);
    for (std::thread& t : threads) t.join();
  }

  if (first_failed.load() < frames.size()) std::rethrow_exception(slots[first_failed.load()].error);
  RunResult result;
  std::map<std::tuple<lang::FileId, std::uint32_t, std::uint32_t, std::string>, bool> seen;
  for (Slot& slot : slots) {
    for (lang::Diagnostic& w : slot.warnings)
      if (seen.emplace(std::make_tuple(w.span.file, w.span.begin.offset, w.span.end.offset, w.message), true)
              .second)
        result.warnings.push_back(std::move(w));
    result.frames.push_back(std::move(*slot.output));
  }
  return result;
}

}  // namespace hlr::runtime
