#include "bench/peers/sketch_peer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace hlr::peers {

namespace {

std::string num(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}

std::string triple(double x, double y, double z) { return "(" + num(x) + "," + num(y) + "," + num(z) + ")"; }

}  // namespace

void write_sketch_input(const Solid& solid, const Camera& camera, const std::filesystem::path& path) {
  if (camera.offset.x != 0 || camera.offset.y != 0)
    throw std::runtime_error("sketch peer: only cameras without a picture offset");
  const bool perspective = camera.projection == hlr::Projection::Perspective;
  std::ofstream out(path);
  if (!out) throw std::runtime_error("sketch peer: cannot write " + path.string());
  const auto& m = camera.viewFromWorld.m;
  const Point3 eye = camera.eye_world();
  out << "def scene {\n";
  for (const Face& face : solid.faces) {
    out << "  polygon";
    for (VertexIndex v : face.rings.front().vertices) {
      const Point3 p = solid.vertices[v];
      out << triple(p.x, p.y, p.z);
    }
    out << "\n";
  }
  out << "}\n";
  // Sketch's view() puts the eye at the origin looking down −z with `up` upward; perspective(p)
  // divides by −z and scales by p: the picture is focal·(right, up)/depth, as ours; in parallel
  // projection scale(focal) gives focal·(right, up), as ours (whose ortho view has the eye at the origin).
  out << "put { view(" << triple(eye.x, eye.y, eye.z) << ","
      << triple(eye.x + m[2][0], eye.y + m[2][1], eye.z + m[2][2]) << ",[" << num(m[1][0]) << ","
      << num(m[1][1]) << "," << num(m[1][2]) << "]) then " << (perspective ? "perspective(" : "scale(")
      << num(camera.focal) << ") } {scene}\n";
  if (!out) throw std::runtime_error("sketch peer: write failed: " + path.string());
}

bool sketch_available() { return std::system("command -v sketch >/dev/null 2>&1") == 0; }

SketchResult run_sketch(const std::filesystem::path& input, bool bsp, int runs, double limit_s) {
  std::filesystem::path output = input;
  output.replace_extension(".tex");
  const std::string command = "timeout " + num(std::ceil(limit_s)) + " sketch " + (bsp ? "-b " : "") +
                              "-o '" + output.string() + "' '" + input.string() + "' >/dev/null 2>&1";
  SketchResult r;
  std::vector<double> times;
  for (int run = 0; run < std::max(1, runs); ++run) {
    const auto t0 = std::chrono::steady_clock::now();
    const int status = std::system(command.c_str());
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (status != 0) {
      r.timed_out = t >= limit_s;
      r.ok = false;
      r.seconds = t;
      return r;
    }
    times.push_back(t);
  }
  std::sort(times.begin(), times.end());
  const std::size_t n = times.size();
  r.seconds = n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
  r.ok = true;
  return r;
}

}  // namespace hlr::peers
