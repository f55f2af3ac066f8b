// Fuzz target: bytes → Program::from_text → frame 0 evaluated. A script that does not parse, or fails
// in evaluation (EvalError; RunError, as hlrscript's run_program expects), is an ordinary outcome; any
// other exception escaping, a crash or a sanitizer report is a finding.
//
// The script lives in an empty directory of its own, so `include` and `import` in fuzzed scripts find
// no real files next to it.
//
// An evaluation that runs long is stopped after kEvaluationLimit through the Ctrl-C flag, which the
// evaluator checks every few thousand steps: a loop that would only end at the step limit (10 million
// steps, about 16 s under the sanitizers) is not a finding, and would otherwise be reported as a timeout.
// Work that never steps (a built-in running away) is not stopped this way, so libFuzzer's -timeout still
// catches it.
#include <stdlib.h>  // mkdtemp

#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>

#include "core/hlr/render_frame.hpp"
#include "runtime/eval_error.hpp"
#include "runtime/interrupt.hpp"
#include "runtime/program.hpp"
#include "runtime/run_error.hpp"
#include "tests/fuzz/fuzz_input.hpp"

namespace {

// An empty temporary directory for the life of the process, removed at exit.
class EmptyDirectory {
 public:
  EmptyDirectory() {
    std::string pattern = (std::filesystem::temp_directory_path() / "hlr-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) std::abort();
    path_ = pattern;
  }
  ~EmptyDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  EmptyDirectory(const EmptyDirectory&) = delete;
  EmptyDirectory& operator=(const EmptyDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

constexpr std::chrono::milliseconds kEvaluationLimit{1000};

// While alive, sets the interrupt flag once `limit` has passed; clears it when destroyed.
class Watchdog {
 public:
  explicit Watchdog(std::chrono::milliseconds limit)
      : thread_([this, limit] {
          std::unique_lock lock(mutex_);
          if (!finished_.wait_for(lock, limit, [this] { return done_; }))
            hlr::runtime::interrupt_requested() = true;
        }) {}
  ~Watchdog() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    finished_.notify_one();
    thread_.join();
    hlr::runtime::interrupt_requested() = false;
  }
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

 private:
  std::mutex mutex_;
  std::condition_variable finished_;
  bool done_ = false;
  std::thread thread_;  // last: it starts once the members it uses exist
};

const std::filesystem::path& script_path() {
  static const EmptyDirectory directory;
  static const std::filesystem::path path = directory.path() / "fuzz.hls";
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(hlr::fuzz::as_text(data, size));
  const auto program = hlr::runtime::Program::from_text("fuzz.hls", text, script_path());
  if (!program->parsed()) return 0;
  const Watchdog watchdog(kEvaluationLimit);
  try {
    (void)program->evaluate_first_frame();
  } catch (const hlr::runtime::EvalError&) {
  } catch (const hlr::runtime::RunError&) {
  } catch (const hlr::RenderCancelled&) {  // the watchdog stopped it
  }
  return 0;
}
