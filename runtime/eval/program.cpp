#include "runtime/eval/program.hpp"

#include <chrono>
#include <stdexcept>

#include "runtime/base/big_stack.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/eval/resolver.hpp"

namespace hlr::runtime {

Program::Program(std::unique_ptr<SourceTable> sources, const SourceEntry* main)
    : sources_(std::move(sources)), main_(main) {
  if (!parsed()) return;
  run_on_big_stack([&] {
    Resolution r = resolve_program(*main_, *sources_);
    static_errors_ = std::move(r.errors);
    uses_frames_ = r.uses_frames;
  });
}

std::unique_ptr<Program> Program::load(const std::filesystem::path& path, const std::string& display_name,
                                       const AccessOptions& access) {
  auto sources = std::make_unique<SourceTable>(FileAccess(resolved_path(path).parent_path(), access));
  std::string error;
  const SourceEntry* main = sources->load(path, display_name, error);
  if (!main) throw EvalError({}, ErrorKind::Input, error);
  return std::unique_ptr<Program>(new Program(std::move(sources), main));
}

std::unique_ptr<Program> Program::from_text(const std::string& display_name, const std::string& text,
                                            const std::filesystem::path& path, const AccessOptions& access) {
  auto sources = std::make_unique<SourceTable>(FileAccess(resolved_path(path).parent_path(), access));
  const SourceEntry* main = sources->add_text(display_name, text, path);
  return std::unique_ptr<Program>(new Program(std::move(sources), main));
}

FrameScene Program::evaluate(const FrameTime& time) const { return evaluate(time, nullptr); }

void Program::release_syntax() {
  sources_->release_syntax();
  released_ = true;
}

FrameScene Program::evaluate(const FrameTime& time,
                             const std::function<void(const Evaluator&)>& inspect) const {
  if (released_) throw std::logic_error("Program::evaluate after release_syntax()");
  if (!parsed())
    throw EvalError(main_->diagnostics, ErrorKind::Script,
                    std::to_string(main_->diagnostics.size()) + " syntax errors in " + main_->source->name());
  if (!static_errors_.empty())
    throw EvalError(static_errors_, ErrorKind::Script,
                    static_errors_.front().message + " in " + main_->source->name());
  FrameScene scene;
  scene.time = time;
  const auto start = std::chrono::steady_clock::now();
  run_on_big_stack([&] {
    Evaluator evaluator(*sources_, scene, limits_);
    scene.deadline = evaluator.budget().deadline();
    evaluator.run(*main_);
    if (inspect) inspect(evaluator);
  });
  scene.evaluate_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return scene;
}

FrameScene Program::evaluate_first_frame(const std::function<void(const Evaluator&)>& inspect) const {
  FrameScene first = evaluate(frame_time(0, 1, kDefaultFps), inspect);
  if (uses_frames_ && first.animation && first.animation->frames > 1)
    first = evaluate(frame_time(0, first.animation->frames, first.animation->fps), inspect);
  return first;
}

FrameTime frame_time(int frame, int frame_count, double fps) {
  FrameTime t;
  t.frame = frame;
  t.t = frame_count > 1 ? static_cast<double>(frame) / (frame_count - 1) : 0;
  t.time = static_cast<double>(frame) / fps;
  t.frames = frame_count;
  return t;
}

}  // namespace hlr::runtime
