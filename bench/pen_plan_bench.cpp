// plan_pen_strokes() on the hidden-line output of generated scenes (bench/bench_scenes.hpp), from 10^2 to
// 10^5 pieces, for the three orders. Each scene is rendered once per process (one engine thread; the
// median CPU time of three renders is `render_cpu_ms`) and its visible pieces laid out on an A4 page
// (home at the page's top-left corner); then only the planner is timed. Counters: pieces, merged (graph
// edges), lifts, lower_bound (Σ max(1, odd/2)), pen_up_mm, pen_down_mm, plan_ms (the planner's own
// wall clock) and plan_cpu_ms (process CPU time; with PlanOptions::threads = 2, both threads), both means
// over the iterations, render_cpu_ms, plan_per_render (plan_cpu_ms / render_cpu_ms), and for Optimized
// vs_greedy (its pen-up over Greedy's) and budget_hit. See bench/README.md.
//   pen_plan_bench --benchmark_filter='City/100000'
#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_scenes.hpp"
#include "bench/command_main.hpp"
#include "core/device/page/page_layout.hpp"
#include "core/hlr/render_frame.hpp"
#include "core/plan/pen_plan.hpp"

namespace {

// Process CPU time in ms: on a shared machine it counts only this process's work (the engine runs one
// thread here, the planner one unless PlanOptions::threads says otherwise).
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) / 1e6;
}

struct PlanInput {
  std::vector<hlr::PlotPiece> pieces;
  double render_ms = 0;
  std::string detail;
  double greedy_pen_up_mm = -1;  // filled on first use
};

const PlanInput& input(const std::string& kind, std::size_t faces) {
  static std::map<std::string, std::unique_ptr<PlanInput>> cache;
  const std::string key = kind + "/" + std::to_string(faces);
  auto it = cache.find(key);
  if (it != cache.end()) return *it->second;
  auto in = std::make_unique<PlanInput>();
  const hlr::bench::BenchScene s = hlr::bench::make_scene(kind, faces);
  hlr::HlrOptions options;
  options.threads = 1;
  hlr::FrameResult result;
  std::vector<double> times;
  for (int i = 0; i < 3; ++i) {
    const double t0 = cpu_ms();
    result = hlr::render_frame(s.scene, s.camera, options);
    times.push_back(cpu_ms() - t0);
  }
  std::sort(times.begin(), times.end());
  in->render_ms = times[1];
  const hlr::PageLayout layout = hlr::fit_to_page(std::nullopt, result.segments, hlr::PageSpec{});
  for (const hlr::VisibleSegment& v : result.segments)
    in->pieces.push_back({layout.to_page_mm(v.s0), layout.to_page_mm(v.s1), 1, hlr::StrokeLayer::Visible});
  in->detail = s.detail;
  return *cache.emplace(key, std::move(in)).first->second;
}

void plan(benchmark::State& state, const char* kind, hlr::PenOrder order, int threads = 1) {
  PlanInput& in = const_cast<PlanInput&>(input(kind, static_cast<std::size_t>(state.range(0))));
  hlr::PlanOptions options;
  options.order = order;
  options.threads = threads;
  hlr::PenPlan result;
  double planning_ms = 0, planning_cpu_ms = 0;
  for (auto _ : state) {
    const double t0 = cpu_ms();
    result = hlr::plan_pen_strokes(in.pieces, options);
    planning_cpu_ms += cpu_ms() - t0;
    planning_ms += result.stats.planning_ms;
    benchmark::DoNotOptimize(result.strokes.data());
  }
  const double iterations = static_cast<double>(std::max<benchmark::IterationCount>(1, state.iterations()));
  planning_ms /= iterations;
  planning_cpu_ms /= iterations;
  const hlr::PlanStats& st = result.stats;
  state.SetLabel(in.detail);
  state.counters["pieces"] = static_cast<double>(st.pieces);
  state.counters["merged"] = static_cast<double>(st.merged_pieces);
  state.counters["lifts"] = static_cast<double>(st.lifts);
  state.counters["lower_bound"] = static_cast<double>(st.lift_lower_bound);
  state.counters["pen_up_mm"] = st.pen_up_mm;
  state.counters["pen_down_mm"] = st.pen_down_mm;
  state.counters["plan_ms"] = planning_ms;
  state.counters["plan_cpu_ms"] = planning_cpu_ms;
  state.counters["render_cpu_ms"] = in.render_ms;
  state.counters["plan_per_render"] = planning_cpu_ms / in.render_ms;
  if (order == hlr::PenOrder::Optimized) {
    if (in.greedy_pen_up_mm < 0) {
      hlr::PlanOptions g = options;
      g.order = hlr::PenOrder::Greedy;
      in.greedy_pen_up_mm = hlr::plan_pen_strokes(in.pieces, g).stats.pen_up_mm;
    }
    state.counters["vs_greedy"] = in.greedy_pen_up_mm > 0 ? st.pen_up_mm / in.greedy_pen_up_mm : 1.0;
    state.counters["effort_capped"] = st.effort_exhausted ? 1 : 0;
  }
}

void BM_CityNone(benchmark::State& s) { plan(s, "city", hlr::PenOrder::None); }
void BM_CityGreedy(benchmark::State& s) { plan(s, "city", hlr::PenOrder::Greedy); }
void BM_CityOptimized(benchmark::State& s) { plan(s, "city", hlr::PenOrder::Optimized); }
// PlanOptions::threads = 2: the greedy comparison plan on a second thread (compare plan_ms, wall clock).
void BM_CityOptimizedThreads2(benchmark::State& s) { plan(s, "city", hlr::PenOrder::Optimized, 2); }
void BM_SphereNone(benchmark::State& s) { plan(s, "sphere", hlr::PenOrder::None); }
void BM_SphereGreedy(benchmark::State& s) { plan(s, "sphere", hlr::PenOrder::Greedy); }
void BM_SphereOptimized(benchmark::State& s) { plan(s, "sphere", hlr::PenOrder::Optimized); }
void BM_MeshNone(benchmark::State& s) { plan(s, "mesh", hlr::PenOrder::None); }
void BM_MeshGreedy(benchmark::State& s) { plan(s, "mesh", hlr::PenOrder::Greedy); }
void BM_MeshOptimized(benchmark::State& s) { plan(s, "mesh", hlr::PenOrder::Optimized); }
void BM_TorusNone(benchmark::State& s) { plan(s, "torus", hlr::PenOrder::None); }
void BM_TorusGreedy(benchmark::State& s) { plan(s, "torus", hlr::PenOrder::Greedy); }
void BM_TorusOptimized(benchmark::State& s) { plan(s, "torus", hlr::PenOrder::Optimized); }

// Sizes are approximate face counts: city 100 … 100000 gives ≈ 130 … 110 000 pieces.
#define PLAN_BENCH(fn, ...) BENCHMARK(fn) __VA_ARGS__->Unit(benchmark::kMillisecond)->UseRealTime()
PLAN_BENCH(BM_CityNone, ->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000));
PLAN_BENCH(BM_CityGreedy, ->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000));
PLAN_BENCH(BM_CityOptimized, ->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000));
PLAN_BENCH(BM_CityOptimizedThreads2, ->Arg(10000)->Arg(100000));
PLAN_BENCH(BM_SphereNone, ->Arg(100)->Arg(10000)->Arg(100000));
PLAN_BENCH(BM_SphereGreedy, ->Arg(100)->Arg(10000)->Arg(100000));
PLAN_BENCH(BM_SphereOptimized, ->Arg(100)->Arg(10000)->Arg(100000));
PLAN_BENCH(BM_MeshNone, ->Arg(1000)->Arg(10000)->Arg(100000));
PLAN_BENCH(BM_MeshGreedy, ->Arg(1000)->Arg(10000)->Arg(100000));
PLAN_BENCH(BM_MeshOptimized, ->Arg(1000)->Arg(10000)->Arg(100000));
PLAN_BENCH(BM_TorusNone, ->Arg(10000)->Arg(100000));
PLAN_BENCH(BM_TorusGreedy, ->Arg(10000)->Arg(100000));
PLAN_BENCH(BM_TorusOptimized, ->Arg(10000)->Arg(100000));

}  // namespace

HLR_BENCHMARK_MAIN()
