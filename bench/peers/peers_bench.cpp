// Peers side by side (issue 12): the same meshes and views through our engine, OpenCASCADE's
// HLRBRep_PolyAlgo and Sketch, one markdown table on stdout. See README.md beside this file.
//   peers_bench [--runs N] [--occt-budget S] [--occt-tol-angular RAD] [--sketch-limit S] [--sketch-bsp]
//   [--no-sketch] [SCENE...]
// SCENE: cube mesh10k mesh75k sphere torus prism, seen in parallel projection along the benchmarks'
// view directions; NAME-persp: through their perspective camera instead (default: cube cube-persp and
// the five meshes).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_scenes.hpp"
#include "bench/peers/occt_peer.hpp"
#include "bench/peers/sketch_peer.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/geometry/box3.hpp"
#include "core/hlr/render_frame.hpp"
#include "core/tolerance.hpp"
#include "stdlib/mesh_import.hpp"

namespace {

using hlr::bench::BenchScene;

struct Options {
  int runs = 5;
  double occt_budget_s = 60;    // stop repeating OCCT's hiding once this much time is spent
  double sketch_limit_s = 300;  // one sketch run longer than this is stopped and reported as such
  double occt_tol_angular = 0;  // > 0: HLRBRep_PolyAlgo::TolAngular (OCCT's default is 0.001 rad)
  bool sketch = true;
  bool sketch_bsp = false;
  std::vector<std::string> scenes;
};

// The same view in parallel projection: eye, direction and up of `perspective`, the picture scale it
// has at the depth of the scene's centre. HLRBRep_PolyAlgo hides in parallel projection only (README).
hlr::Camera parallel_view(const BenchScene& b, const hlr::Camera& perspective) {
  const hlr::Solid& solid = *b.scene.objects.front().solid;
  hlr::Point3 lo = solid.vertices.front(), hi = lo;
  for (hlr::Point3 p : solid.vertices) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double depth = perspective.view({0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y), 0.5 * (lo.z + hi.z)}).z;
  const hlr::Point3 eye = perspective.eye_world();
  const auto& m = perspective.viewFromWorld.m;
  const hlr::Vector3 forward{m[2][0], m[2][1], m[2][2]}, up{m[1][0], m[1][1], m[1][2]};
  return hlr::ortho_camera({eye, eye + depth * forward, up, 2 * depth / perspective.focal, 0});
}

// "NAME" is seen in parallel projection, "NAME-persp" through the benchmarks' perspective camera.
BenchScene make(const std::string& full_name) {
  const bool persp = full_name.size() > 6 && full_name.ends_with("-persp");
  const std::string name = persp ? full_name.substr(0, full_name.size() - 6) : full_name;
  BenchScene b;
  if (name == "cube") {
    b.scene.objects.push_back({"cube", hlr::stdlib::box({-1, -1, -1}, {1, 1, 1})});
    b.camera = hlr::bench::orbit_view({0, 0, 0}, 6, 30, 25, 40);
    b.faces = 6;
    b.detail = "box (2 × 2 × 2)";
  } else if (name == "mesh10k") {
    b = hlr::bench::make_scene("mesh", 10000);
  } else if (name == "mesh75k") {
    b = hlr::bench::make_scene("mesh", 75000);
  } else if (name == "sphere") {
    b = hlr::bench::make_scene("sphere", 5000);
  } else if (name == "torus") {
    b = hlr::bench::make_scene("torus", 10000);
  } else if (name == "prism") {
    b = hlr::bench::make_scene("prism", 2002);
  } else if (name.ends_with(".off") || name.ends_with(".stl") || name.ends_with(".obj")) {
    // A mesh file (the bunny, fandisk), imported as `hlrscript` does, seen from 2.2 diagonals away.
    auto solid = std::make_shared<hlr::Solid>(hlr::stdlib::import_mesh(name).solid);
    hlr::Box3 box;
    for (hlr::Point3 p : solid->vertices) box.include(p);
    const hlr::Point3 centre{0.5 * (box.lo.x + box.hi.x), 0.5 * (box.lo.y + box.hi.y),
                             0.5 * (box.lo.z + box.hi.z)};
    b.faces = solid->faces.size();
    b.scene.objects.push_back({std::filesystem::path(name).filename().string(), solid});
    b.camera = hlr::bench::orbit_view(centre, 2.2 * hlr::distance(box.lo, box.hi), 30, 25, 40);
    b.detail = "import(\"" + std::filesystem::path(name).filename().string() + "\")";
  } else {
    throw std::invalid_argument(
        "unknown scene '" + full_name +
        "' (cube mesh10k mesh75k sphere torus prism, or a mesh file FILE.off|.stl|.obj; each optionally "
        "with -persp)");
  }
  if (!persp) b.camera = parallel_view(b, b.camera);
  return b;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Ours {
  double one_thread_s = 0, all_threads_s = 0, visible_length = 0;
  std::size_t segments = 0;
};

// Median of `runs` render_frame() calls after one untimed warm-up (which also finds the solid's
// self-crossings, kept with the solid as in an animation).
double time_render(const BenchScene& s, unsigned threads, int runs, hlr::FrameResult& last) {
  hlr::HlrOptions options;
  options.threads = threads;
  last = hlr::render_frame(s.scene, s.camera, options);
  std::vector<double> times;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    last = hlr::render_frame(s.scene, s.camera, options);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return median(times);
}

Ours run_ours(const BenchScene& s, int runs) {
  Ours o;
  hlr::FrameResult result;
  o.all_threads_s = time_render(s, 0, runs, result);
  o.one_thread_s = time_render(s, 1, runs, result);
  for (const hlr::VisibleSegment& seg : result.segments)
    if (!seg.hidden) {
      o.visible_length += std::hypot(seg.s1.x - seg.s0.x, seg.s1.y - seg.s0.y);
      ++o.segments;
    }
  return o;
}

std::string ms(double s) {
  char b[32];
  if (s < 0.001)
    std::snprintf(b, sizeof b, "%.3f ms", 1e3 * s);
  else if (s < 0.01)
    std::snprintf(b, sizeof b, "%.2f ms", 1e3 * s);
  else if (s < 1)
    std::snprintf(b, sizeof b, "%.1f ms", 1e3 * s);
  else
    std::snprintf(b, sizeof b, "%.2f s", s);
  return b;
}

std::string fixed(double v, int digits) {
  char b[48];
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}

std::string sci(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1e", v);
  return b;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> double {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return std::stod(argv[++i]);
    };
    if (a == "--runs")
      o.runs = std::max(1, static_cast<int>(value()));
    else if (a == "--occt-budget")
      o.occt_budget_s = value();
    else if (a == "--occt-tol-angular")
      o.occt_tol_angular = value();
    else if (a == "--sketch-limit")
      o.sketch_limit_s = value();
    else if (a == "--sketch-bsp")
      o.sketch_bsp = true;
    else if (a == "--no-sketch")
      o.sketch = false;
    else if (a == "-h" || a == "--help")
      throw std::invalid_argument("usage");
    else
      o.scenes.push_back(a);
  }
  if (o.scenes.empty()) o.scenes = {"cube", "cube-persp", "mesh10k", "mesh75k", "sphere", "torus", "prism"};
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  try {
    opt = parse(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr,
                 "%s\nusage: peers_bench [--runs N] [--occt-budget S] [--occt-tol-angular RAD] "
                 "[--sketch-limit S] [--sketch-bsp] "
                 "[--no-sketch] [SCENE[-persp]]... (SCENE: cube mesh10k mesh75k sphere torus prism, or a "
                 "mesh file FILE.off|.stl|.obj)\n",
                 e.what());
    return 2;
  }
  const bool sketch = opt.sketch && hlr::peers::sketch_available();
  if (opt.sketch && !sketch) std::fprintf(stderr, "sketch not found on PATH: its columns stay empty\n");
  const std::filesystem::path work = std::filesystem::temp_directory_path() / "hlr-peers";
  std::filesystem::create_directories(work);

  std::printf(
      "| scene | generator | faces | ours, 1 thread | ours, all threads | ours: visible length (pieces) "
      "| OCCT build | OCCT hide | OCCT ÷ ours | OCCT visible length (pieces) | disagreement | "
      "OCCT smooth visible length (not compared) | Sketch%s | Sketch ÷ ours |\n",
      opt.sketch_bsp ? " -b" : "");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::fflush(stdout);
  int status = 0;
  std::vector<std::string> notes;
  for (const std::string& name : opt.scenes) {
    try {
      const BenchScene s = make(name);
      const hlr::Solid& solid = *s.scene.objects.front().solid;
      const Ours ours = run_ours(s, opt.runs);
      const hlr::peers::OcctResult occt = hlr::peers::run_occt(
          solid, s.camera, opt.runs, opt.occt_budget_s, name.rfind("cube", 0) == 0, opt.occt_tol_angular);
      const double disagreement = std::abs(ours.visible_length - occt.visible_length) / ours.visible_length;
      std::string sketch_time = "—", sketch_ratio = "—";
      if (sketch) {
        const std::filesystem::path input = work / (name + ".sk");
        hlr::peers::write_sketch_input(solid, s.camera, input);
        const hlr::peers::SketchResult sk =
            hlr::peers::run_sketch(input, opt.sketch_bsp, opt.runs, opt.sketch_limit_s);
        if (sk.ok) {
          sketch_time = ms(sk.seconds);
          sketch_ratio = fixed(sk.seconds / ours.one_thread_s, 1) + "×";
        } else {
          sketch_time = sk.timed_out ? "> " + ms(opt.sketch_limit_s) : "failed";
          sketch_ratio = sk.timed_out ? "> " + fixed(opt.sketch_limit_s / ours.one_thread_s, 0) + "×" : "—";
        }
      }
      std::printf("| %s | %s | %zu | %s | %s | %s (%zu) | %s | %s%s | %s× | %s (%zu) | %s | %s | %s | %s |\n",
                  name.c_str(), s.detail.c_str(), s.faces, ms(ours.one_thread_s).c_str(),
                  ms(ours.all_threads_s).c_str(), fixed(ours.visible_length, 6).c_str(), ours.segments,
                  ms(occt.build_s).c_str(), ms(occt.hide_s).c_str(),
                  occt.runs < opt.runs ? (" (" + std::to_string(occt.runs) + " run)").c_str() : "",
                  fixed(occt.hide_s / ours.one_thread_s, 1).c_str(), fixed(occt.visible_length, 6).c_str(),
                  occt.visible_pieces, sci(disagreement).c_str(),
                  fixed(occt.smooth_visible_length, 3).c_str(), sketch_time.c_str(), sketch_ratio.c_str());
      std::fflush(stdout);
      if (name.rfind("cube", 0) == 0) {
        notes.push_back(name + ": ours " + fixed(ours.visible_length, 9) + ", OCCT (Hide() pieces) " +
                        fixed(occt.visible_length, 9) + ", HLRBRep_PolyHLRToShape compounds " +
                        fixed(occt.to_shape_length, 9) + " (" + ms(occt.to_shape_s) + ")");
        // The gate (parallel projection): the engines agree to rounding, as they do (3e-16).
        if (name == "cube" && !(disagreement <= hlr::Tolerance::kRelative)) {
          std::fprintf(stderr, "%s check failed: ours %.12g, OCCT %.12g\n", name.c_str(), ours.visible_length,
                       occt.visible_length);
          status = 1;
        }
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", name.c_str(), e.what());
      status = 1;
    }
  }
  if (!notes.empty()) std::printf("\n");
  for (const std::string& n : notes) std::printf("%s\n", n.c_str());
  return status;
}
