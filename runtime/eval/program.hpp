// A script ready to run: its files (main script and includes) and the entry point that evaluates it for
// one frame. Parse once, evaluate per frame; evaluate() is const and thread-safe, so frames can be
// evaluated in parallel.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "runtime/base/file_access.hpp"
#include "runtime/base/limits.hpp"
#include "runtime/base/source_table.hpp"
#include "runtime/eval/frame_scene.hpp"

namespace hlr::runtime {

class Evaluator;

class Program {
 public:
  // Reads and parses the script. Throws EvalError of kind Input (no diagnostics, the reason in what())
  // when it cannot be read. A script with syntax errors loads, with syntax_errors() set.
  // `access` adds the folders the script may read and where its outputs go (file_access.hpp); the
  // script's own folder is always readable.
  static std::unique_ptr<Program> load(const std::filesystem::path& path, const std::string& display_name,
                                       const AccessOptions& access = {});
  // A script given as text; includes resolve against `path`'s directory.
  static std::unique_ptr<Program> from_text(const std::string& display_name, const std::string& text,
                                            const std::filesystem::path& path = "script.hls",
                                            const AccessOptions& access = {});

  bool parsed() const { return main_->script.has_value(); }
  const std::vector<lang::Diagnostic>& syntax_errors() const { return main_->diagnostics; }
  // What the resolver (runtime/eval/resolver.hpp) found in the whole program when it was loaded: unknown
  // names, calls whose arguments do not fit. evaluate() throws them before running anything.
  const std::vector<lang::Diagnostic>& static_errors() const { return static_errors_; }

  // Frame 0, the evaluation that says how long the sequence is. A script that reads `frames` is
  // evaluated again once the animate statement has told N, so frame 0 sees what every other frame sees.
  FrameScene evaluate_first_frame(const std::function<void(const Evaluator&)>& inspect = nullptr) const;

  // Evaluates the whole script with `frame`, `t` and `time` bound. Throws EvalError (also for a script
  // with syntax errors or static errors). Runs on a thread with a large stack (big_stack.hpp), so no script
  // can overflow the caller's.
  FrameScene evaluate(const FrameTime& time) const;
  // The same, then `inspect` sees the evaluator (its top-level names) before it is gone (the REPL).
  FrameScene evaluate(const FrameTime& time, const std::function<void(const Evaluator&)>& inspect) const;

  const SourceTable& sources() const { return *sources_; }
  // Frees the syntax trees of the script and its includes, keeping their text for messages: for a run
  // whose last evaluation is done, so that the hidden lines do not share the peak memory with a tree
  // that, for a generated scene, is larger than the scene's solids. evaluate() throws from then on.
  void release_syntax();
  // The run's limits (--limit, --frame-timeout), for every evaluation from here on.
  void set_limits(const Limits& limits) { limits_ = limits; }
  const Limits& limits() const { return limits_; }
  const SourceEntry& main() const { return *main_; }

 private:
  explicit Program(std::unique_ptr<SourceTable> sources, const SourceEntry* main);

  std::unique_ptr<SourceTable> sources_;  // grows as includes are loaded (internally synchronised)
  const SourceEntry* main_;
  std::vector<lang::Diagnostic> static_errors_;
  bool uses_frames_ = false;
  bool released_ = false;
  Limits limits_;
};

// `frame`, `t` = frame/(N − 1) (0 for one frame) and `time` = frame/fps.
FrameTime frame_time(int frame, int frame_count, double fps);

}  // namespace hlr::runtime
