// The whole frame pipeline, as `hlrscript SCRIPT -o OUT --jobs N` runs it (in-process, through run_cli):
// sequences to PNG, PDF and HPGL with one and two threads, the flagship landing approach, and the
// 100k-face turntable. Counters: frames, frames per second. The solid cache is emptied before every
// run, so each run pays what a fresh process pays. Peak memory over long sequences: pipeline_memory.sh.
//   pipeline_bench --benchmark_filter='Turntable30k' --benchmark_min_time=2
#include <benchmark/benchmark.h>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "bench/command_main.hpp"
#include "runtime/builtins/solid_cache.hpp"
#include "runtime/cli/cli.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kSource = HLR_SOURCE_DIR;

// The frame count the command reports ("wrote …: 48 frames, …"), so the rate follows the script.
int frames_written(const std::string& report) {
  std::smatch m;
  static const std::regex kFrames(R"(: (\d+) frames?,)");
  return std::regex_search(report, m, kFrames) ? std::stoi(m[1].str()) : 0;
}

void run(benchmark::State& state, const std::string& script, const std::string& pattern) {
  const fs::path dir = fs::temp_directory_path() / "hlr-pipeline-bench";
  fs::create_directories(dir);
  const std::string jobs = std::to_string(state.range(0));
  const std::string out = (dir / pattern).string();
  const std::string path = (kSource / script).string();
  std::vector<const char*> argv = {"hlrscript", path.c_str(), "-o", out.c_str(), "--jobs", jobs.c_str()};
  int frames = 0;
  for (auto _ : state) {
    hlr::runtime::SolidCache::shared().clear();
    std::ostringstream o, e;
    if (hlr::runtime::run_cli(static_cast<int>(argv.size()), argv.data(), o, e) != 0) {
      state.SkipWithError(e.str().c_str());
      break;
    }
    frames = frames_written(o.str());
  }
  state.counters["frames"] = frames;
  state.counters["fps"] = benchmark::Counter(frames, benchmark::Counter::kIsIterationInvariantRate);
  fs::remove_all(dir);
}

void Turntable30kPng(benchmark::State& s) { run(s, "bench/scenes/turntable-30k.hls", "tt-{frame:03}.png"); }
void Turntable30kPdf(benchmark::State& s) { run(s, "bench/scenes/turntable-30k.hls", "tt.pdf"); }
void Turntable30kHpgl(benchmark::State& s) { run(s, "bench/scenes/turntable-30k.hls", "tt-{frame:03}.hpgl"); }
void Turntable100kPdf(benchmark::State& s) { run(s, "bench/scenes/turntable-100k.hls", "tt.pdf"); }
void LandingPdf(benchmark::State& s) { run(s, "examples/desens/landing.hls", "landing.pdf"); }
void LandingHpgl(benchmark::State& s) { run(s, "examples/desens/landing.hls", "landing-{frame:03}.hpgl"); }

}  // namespace

BENCHMARK(Turntable30kPng)->Arg(1)->Arg(2)->ArgName("jobs")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Turntable30kPdf)->Arg(1)->Arg(2)->ArgName("jobs")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Turntable30kHpgl)->Arg(1)->Arg(2)->ArgName("jobs")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Turntable100kPdf)->Arg(1)->Arg(2)->ArgName("jobs")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(LandingPdf)->Arg(1)->Arg(2)->ArgName("jobs")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(LandingHpgl)->Arg(1)->Arg(2)->ArgName("jobs")->Unit(benchmark::kMillisecond)->UseRealTime();

HLR_BENCHMARK_MAIN()
