// Fuzz target: bytes → Program::from_text → frame 0 evaluated. A script that does not parse, or fails
// in evaluation (EvalError; RunError, as hlrscript's run_program expects), is an ordinary outcome; any
// other exception escaping, a crash or a sanitizer report is a finding.
//
// The script lives in an empty directory of its own, so `include` and `import` in fuzzed scripts find
// no real files next to it.
//
// The run has small limits, as `--limit` and `--frame-timeout` would set them: a loop that runs long
// stops at the step limit or the frame budget with an ordinary located error, so only work that never
// steps (a built-in running away) can reach libFuzzer's -timeout, and that is a finding.
#include <stdlib.h>  // mkdtemp

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include "runtime/base/eval_error.hpp"
#include "runtime/base/limits.hpp"
#include "runtime/eval/program.hpp"
#include "runtime/pipeline/run_error.hpp"
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

// Small enough that each input takes milliseconds, large enough for every seed to reach its frame.
hlr::runtime::Limits fuzz_limits() {
  hlr::runtime::Limits limits;
  limits.steps = 200'000;
  limits.faces = 20'000;
  limits.vertices = 100'000;
  limits.segments = 100'000;
  limits.memory_mb = 64;
  limits.list = 100'000;
  limits.string = 1'000'000;
  limits.frame_timeout_s = 1.0;
  return limits;
}

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
  program->set_limits(fuzz_limits());
  try {
    (void)program->evaluate_first_frame();
  } catch (const hlr::runtime::EvalError&) {
  } catch (const hlr::runtime::RunError&) {
  }
  return 0;
}
