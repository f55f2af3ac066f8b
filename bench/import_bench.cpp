// Mesh import (stdlib/mesh_*.cpp) at the sizes people import: the bumpy closed triangle mesh of 10^4 to
// 10^6 faces written as OFF, OBJ, ASCII STL and binary STL text in memory (by this program, with
// std::to_chars: shortest round-trip numbers, as exporters write them), then parsed, repaired and built
// into a Solid. Counters: faces, bytes, MB/s of input. bench/README.md has the figures.
//   import_bench --benchmark_filter='Off/75000'
#include <benchmark/benchmark.h>

#include <charconv>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "bench/command_main.hpp"
#include "core/camera/lookat_camera.hpp"
#include "core/geometry/box3.hpp"
#include "core/hlr/render_frame.hpp"
#include "stdlib/generators.hpp"
#include "stdlib/mesh_import.hpp"

namespace {

void append_number(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void append_point(std::string& out, hlr::Point3 p) {
  append_number(out, p.x);
  out += ' ';
  append_number(out, p.y);
  out += ' ';
  append_number(out, p.z);
}

std::string off_text(const hlr::Solid& s) {
  std::string out =
      "OFF\n" + std::to_string(s.vertices.size()) + " " + std::to_string(s.faces.size()) + " 0\n";
  for (hlr::Point3 p : s.vertices) {
    append_point(out, p);
    out += '\n';
  }
  for (const hlr::Face& f : s.faces) {
    out += std::to_string(f.rings[0].vertices.size());
    for (hlr::VertexIndex v : f.rings[0].vertices) out += ' ' + std::to_string(v);
    out += '\n';
  }
  return out;
}

std::string obj_text(const hlr::Solid& s) {
  std::string out = "o mesh\n";
  for (hlr::Point3 p : s.vertices) {
    out += "v ";
    append_point(out, p);
    out += '\n';
  }
  for (const hlr::Face& f : s.faces) {
    out += 'f';
    for (hlr::VertexIndex v : f.rings[0].vertices) out += ' ' + std::to_string(v + 1);
    out += '\n';
  }
  return out;
}

std::string stl_ascii(const hlr::Solid& s) {
  std::string out = "solid mesh\n";
  for (const hlr::Face& f : s.faces) {
    out += "facet normal 0 0 0\n outer loop\n";
    for (hlr::VertexIndex v : f.rings[0].vertices) {
      out += "  vertex ";
      append_point(out, s.vertices[v]);
      out += '\n';
    }
    out += " endloop\nendfacet\n";
  }
  out += "endsolid mesh\n";
  return out;
}

std::string stl_binary(const hlr::Solid& s) {
  std::string out(80, ' ');
  const auto n = static_cast<std::uint32_t>(s.faces.size());
  out.append(reinterpret_cast<const char*>(&n), 4);
  for (const hlr::Face& f : s.faces) {
    float rec[12] = {};
    for (int k = 0; k < 3; ++k) {
      const hlr::Point3 p = s.vertices[f.rings[0].vertices[static_cast<std::size_t>(k)]];
      rec[3 + 3 * k] = static_cast<float>(p.x), rec[4 + 3 * k] = static_cast<float>(p.y),
                  rec[5 + 3 * k] = static_cast<float>(p.z);
    }
    out.append(reinterpret_cast<const char*>(rec), sizeof rec);
    out.append(2, '\0');
  }
  return out;
}

// One mesh per size, kept while the benchmarks of that size run.
const hlr::Solid& mesh(int faces) {
  static std::pair<int, hlr::Solid> cache{-1, {}};
  if (cache.first != faces) cache = {faces, hlr::stdlib::closed_mesh(faces, 1)};
  return cache.second;
}

template <typename Make, typename Import>
void run(benchmark::State& state, Make make, Import import) {
  const hlr::Solid& solid = mesh(static_cast<int>(state.range(0)));
  const std::string data = make(solid);
  std::size_t faces = 0;
  for (auto _ : state) {
    const hlr::stdlib::ImportedMesh m = import(data);
    faces = m.solid.faces.size();
    benchmark::DoNotOptimize(faces);
  }
  state.counters["faces"] = static_cast<double>(faces);
  state.counters["MB"] = static_cast<double>(data.size()) / 1e6;
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(data.size()));
}

void Off(benchmark::State& s) {
  run(s, off_text, [](const std::string& d) { return hlr::stdlib::import_off(d, "mesh.off"); });
}
void Obj(benchmark::State& s) {
  run(s, obj_text, [](const std::string& d) { return hlr::stdlib::import_obj(d, "mesh.obj"); });
}
void StlAscii(benchmark::State& s) {
  run(s, stl_ascii, [](const std::string& d) { return hlr::stdlib::import_stl(d, "mesh.stl"); });
}
void StlBinary(benchmark::State& s) {
  run(s, stl_binary, [](const std::string& d) { return hlr::stdlib::import_stl(d, "mesh.stl"); });
}

// The solid of a mesh file, or none (the benchmark then reports the import's error and stops).
std::optional<hlr::Solid> import_or_skip(const std::string& path, benchmark::State& state) {
  try {
    return hlr::stdlib::import_mesh(path).solid;
  } catch (const hlr::stdlib::MeshImportError& e) {
    state.SkipWithError(e.what());
    return std::nullopt;
  }
}

// Real meshes, when HLR_IMPORT_FILES lists them (paths separated by ':'): import_mesh() on each file as
// `import()` runs it, reading included (the file stays in the page cache). bench/cgal_meshes.sh fetches
// the CGAL demo meshes the issue measured (bunny00.off, fandisk_large.off).
const bool kFilesRegistered = [] {
  const char* list = std::getenv("HLR_IMPORT_FILES");
  for (std::string_view rest = list ? list : ""; !rest.empty();) {
    const std::size_t colon = rest.find(':');
    const std::string path(rest.substr(0, colon));
    rest = colon == std::string_view::npos ? std::string_view{} : rest.substr(colon + 1);
    if (path.empty()) continue;
    const std::string file = std::filesystem::path(path).filename().string();
    benchmark::RegisterBenchmark(("File/" + file).c_str(), [path](benchmark::State& state) {
      std::size_t faces = 0;
      try {
        for (auto _ : state) {
          faces = hlr::stdlib::import_mesh(path).solid.faces.size();
          benchmark::DoNotOptimize(faces);
        }
      } catch (const hlr::stdlib::MeshImportError& e) {
        state.SkipWithError(e.what());
        return;
      }
      const auto bytes = std::filesystem::file_size(path);
      state.counters["faces"] = static_cast<double>(faces);
      state.counters["MB"] = static_cast<double>(bytes) / 1e6;
      state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                              static_cast<std::int64_t>(bytes));
    })->Unit(benchmark::kMillisecond);
    // The search for the mesh's faces that cross each other (Solid::self_crossings, the first frame's
    // largest single cost on a scan), on a fresh copy each iteration (the copy is not timed).
    benchmark::RegisterBenchmark(("FileSelfCrossings/" + file).c_str(),
                                 [path](benchmark::State& state) {
                                   const std::optional<hlr::Solid> mesh = import_or_skip(path, state);
                                   if (!mesh) return;
                                   std::optional<hlr::Solid> copy;
                                   std::size_t found = 0;
                                   for (auto _ : state) {
                                     state.PauseTiming();
                                     copy.reset();
                                     copy.emplace(*mesh);
                                     state.ResumeTiming();
                                     found = copy->self_crossings().size();
                                     benchmark::DoNotOptimize(found);
                                   }
                                   state.counters["faces"] = static_cast<double>(mesh->faces.size());
                                   state.counters["crossings"] = static_cast<double>(found);
                                 })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    // The first frame's hidden lines (self-crossing search included), the eye above and to the side of
    // the mesh about 1.6 times its size from its centre, as bench/peers/whole_run.py looks at it.
    benchmark::RegisterBenchmark(
        ("FileHiddenLines/" + file).c_str(),
        [path](benchmark::State& state) {
          const std::optional<hlr::Solid> mesh = import_or_skip(path, state);
          if (!mesh) return;
          hlr::Box3 box;
          for (const hlr::Point3& p : mesh->vertices) box.include(p);
          const hlr::Point3 centre = hlr::lerp(box.lo, box.hi, 0.5);
          hlr::LookatParameters view;
          view.eye = centre + 0.5 * box.largest_side() * hlr::Vector3{1.6, -2.4, 1.2};
          view.target = centre;
          view.fov_deg = 30;
          const hlr::Camera camera = hlr::lookat_camera(view);
          hlr::Scene scene;
          std::size_t pieces = 0;
          for (auto _ : state) {
            state.PauseTiming();
            scene.objects.clear();
            scene.objects.push_back({"mesh", *mesh});
            state.ResumeTiming();
            pieces = hlr::render_frame(scene, camera).segments.size();
            benchmark::DoNotOptimize(pieces);
          }
          state.counters["faces"] = static_cast<double>(mesh->faces.size());
          state.counters["pieces"] = static_cast<double>(pieces);
        })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  return true;
}();

}  // namespace

// 75 000 faces is the Stanford bunny's size (69 451 triangles in CGAL's bunny.off, 72 027 in others).
BENCHMARK(Off)->Arg(10000)->Arg(75000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(Obj)->Arg(75000)->Unit(benchmark::kMillisecond);
BENCHMARK(StlAscii)->Arg(75000)->Unit(benchmark::kMillisecond);
BENCHMARK(StlBinary)->Arg(75000)->Arg(1000000)->Unit(benchmark::kMillisecond);

HLR_BENCHMARK_MAIN()
