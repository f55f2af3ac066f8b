// render_frame() on generated scenes from 10^2 to 10^6 faces: box cities, tessellated spheres and tori,
// the bumpy closed triangle mesh. Counters: faces, visible segments, candidate edges, edge–face tests,
// faces per second, and the process's peak RSS (VmHWM — cumulative over the run, so per-scene peaks
// come from memory_bench, which renders one scene per process). See bench/README.md.
//   hlr_bench --benchmark_filter='city' --benchmark_min_time=0.1
// HLR_BENCH_THREADS=n sets the engine's threads (default 1, for per-core numbers; 0 = all cores).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "bench/bench_scenes.hpp"
#include "bench/command_main.hpp"
#include "core/hlr/render_frame.hpp"

namespace {

using hlr::bench::BenchScene;

// Building a 10^6-face scene takes seconds, and the benchmark function runs several times while the
// library sizes its iterations: keep the last scene.
const BenchScene& scene(const std::string& kind, std::size_t faces) {
  static std::pair<std::string, std::unique_ptr<BenchScene>> cache;
  const std::string key = kind + "/" + std::to_string(faces);
  if (cache.first != key) {
    cache.second.reset();  // free the previous scene first: peak memory stays one scene
    cache = {key, std::make_unique<BenchScene>(hlr::bench::make_scene(kind, faces))};
  }
  return *cache.second;
}

unsigned engine_threads() {
  const char* t = std::getenv("HLR_BENCH_THREADS");
  return t ? static_cast<unsigned>(std::strtoul(t, nullptr, 10)) : 1u;
}

void render(benchmark::State& state, const char* kind, unsigned max_level = 0) {
  const BenchScene& s = scene(kind, static_cast<std::size_t>(state.range(0)));
  hlr::HlrOptions options;
  options.threads = engine_threads();
  options.max_level = max_level;
  hlr::FrameResult result;
  for (auto _ : state) {
    result = hlr::render_frame(s.scene, s.camera, options);
    benchmark::DoNotOptimize(result.segments.data());
  }
  state.SetLabel(s.detail);
  state.counters["faces"] = static_cast<double>(s.faces);
  state.counters["segments"] = static_cast<double>(result.stats.visible_segments);
  state.counters["candidates"] = static_cast<double>(result.stats.candidate_edges);
  state.counters["face_tests"] = static_cast<double>(result.stats.face_tests);
  state.counters["faces_per_s"] =
      benchmark::Counter(static_cast<double>(s.faces), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_rss_MB"] = static_cast<double>(hlr::bench::peak_rss_bytes()) / (1 << 20);
}

// Finding where a solid's faces cross each other (Solid::self_crossings), which the engine does once per
// solid and keeps: each iteration asks a fresh copy (copying is not timed).
void self_crossings(benchmark::State& state, const char* kind) {
  const BenchScene& s = scene(kind, static_cast<std::size_t>(state.range(0)));
  const hlr::Solid& solid = *s.scene.objects.front().solid;
  std::size_t found = 0;
  std::optional<hlr::Solid> copy;
  for (auto _ : state) {
    state.PauseTiming();
    copy.reset();
    copy.emplace(solid);
    state.ResumeTiming();
    found = copy->self_crossings().size();
    benchmark::DoNotOptimize(found);
  }
  state.counters["faces"] = static_cast<double>(solid.faces.size());
  state.counters["crossings"] = static_cast<double>(found);
  state.counters["faces_per_s"] = benchmark::Counter(static_cast<double>(solid.faces.size()),
                                                     benchmark::Counter::kIsIterationInvariantRate);
}

void BM_City(benchmark::State& state) { render(state, "city"); }
void BM_Sphere(benchmark::State& state) { render(state, "sphere"); }
void BM_Torus(benchmark::State& state) { render(state, "torus"); }
void BM_ClosedMesh(benchmark::State& state) { render(state, "mesh"); }
void BM_Prism(benchmark::State& state) { render(state, "prism"); }
// Occlusion levels 1 … range(1) besides the visible lines (0: the visible lines alone, culling on).
void BM_LevelsMesh(benchmark::State& state) { render(state, "mesh", static_cast<unsigned>(state.range(1))); }
void BM_LevelsCity(benchmark::State& state) { render(state, "city", static_cast<unsigned>(state.range(1))); }
void BM_SelfCrossingsTorus(benchmark::State& state) { self_crossings(state, "torus"); }
void BM_SelfCrossingsMesh(benchmark::State& state) { self_crossings(state, "mesh"); }

// Sizes are approximate face counts.
BENCHMARK(BM_City)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Sphere)->Arg(100)->Arg(10000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Torus)->Arg(100)->Arg(10000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ClosedMesh)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Prism)->Arg(2000)->Arg(20000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_LevelsMesh)
    ->Args({100000, 0})
    ->Args({100000, 3})
    ->ArgNames({"faces", "levels"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_LevelsCity)
    ->Args({10000, 0})
    ->Args({10000, 3})
    ->ArgNames({"faces", "levels"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_SelfCrossingsTorus)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SelfCrossingsMesh)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace

HLR_BENCHMARK_MAIN()
