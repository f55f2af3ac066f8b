// Scenes shared by the benchmark programs (hlr_bench, memory_bench): each is named by a kind and an
// approximate face count, so that "city 100000" means the same scene in both programs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/camera/lookat_camera.hpp"
#include "core/hlr/scene.hpp"
#include "stdlib/generators.hpp"

namespace hlr::bench {

struct BenchScene {
  Scene scene;
  Camera camera;
  std::size_t faces = 0;
  std::string detail;  // the generator call, for the report
};

inline std::size_t count_faces(const Scene& s) {
  std::size_t n = 0;
  for (const auto& o : s.objects) n += o.solid->faces.size();
  return n;
}

// A camera looking at `target` from azimuth/elevation (degrees) at `distance`.
inline Camera orbit_view(Point3 target, double distance, double azimuth_deg, double elevation_deg, double fov) {
  const double az = azimuth_deg * std::numbers::pi / 180, el = elevation_deg * std::numbers::pi / 180;
  const Vector3 dir{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
  return lookat_camera(LookatParameters{target + distance * dir, target, {0, 0, 1}, fov, 0, 0});
}

// kind: city | sphere | torus | mesh | prism; faces: the approximate face count wanted.
inline BenchScene make_scene(const std::string& kind, std::size_t faces) {
  BenchScene b;
  const double f = static_cast<double>(faces);
  char detail[160];
  if (kind == "city") {
    // ≈ 6.3 faces per building (boxes, and 15% eight-faced towers), plus the ground plate.
    const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(f / 6.3))));
    const stdlib::CityOptions o;
    int i = 0;
    for (Solid& s : stdlib::box_city(n, n, 1, o)) {
      std::string name = "b";  // (built with +=: GCC 12 warns falsely on "b" + std::string)
      name += std::to_string(i++);
      b.scene.objects.push_back({std::move(name), std::move(s)});
    }
    const double side = n * o.cell;
    // Seen from 35° above the horizon: the buildings' heights do not grow with n, so each line of
    // sight crosses about the same number of buildings (roughly constant depth complexity).
    b.camera = orbit_view({0.5 * side, 0.5 * side, 0}, 1.1 * side + 60, 30, 35, 60);
    std::snprintf(detail, sizeof detail, "box_city(%d, %d, 1)", n, n);
  } else if (kind == "sphere") {
    const int n = std::max(3, static_cast<int>(std::lround(std::sqrt(f / 2))));
    b.scene.objects.push_back({"sphere", stdlib::sphere({0, 0, 0}, 1, 2 * n, n, 0)});
    b.camera = orbit_view({0, 0, 0}, 4, 20, 25, 40);
    std::snprintf(detail, sizeof detail, "sphere(%d slices, %d stacks, crease 0)", 2 * n, n);
  } else if (kind == "torus") {
    // Crease 20°: a smooth surface, drawn by its contour (plus the creases the coarse meshes have).
    const int n = std::max(3, static_cast<int>(std::lround(std::sqrt(f / 4))));
    b.scene.objects.push_back({"torus", stdlib::torus({0, 0, 0}, 2, 0.7, 4 * n, n, 20)});
    b.camera = orbit_view({0, 0, 0}, 8, 20, 35, 40);
    std::snprintf(detail, sizeof detail, "torus(%d x %d, crease 20)", 4 * n, n);
  } else if (kind == "mesh") {
    b.scene.objects.push_back({"mesh", stdlib::closed_mesh(static_cast<int>(faces), 1)});
    b.camera = orbit_view({0, 0, 0}, 4, 20, 25, 40);
    std::snprintf(detail, sizeof detail, "closed_mesh(%zu, 1)", faces);
  } else if (kind == "prism") {
    // An n-sided prism (faces ≈ n + 2) with every side edge drawn: two faces of n vertices each, the
    // case where cost must follow the visible pieces, not the size of a face.
    const int n = std::max(3, static_cast<int>(faces) - 2);
    b.scene.objects.push_back({"prism", stdlib::cylinder({0, 0, 0}, 1, 1.5, n, 0)});
    b.camera = orbit_view({0, 0, 0.75}, 5, 20, 30, 40);
    std::snprintf(detail, sizeof detail, "cylinder(%d sides, crease 0)", n);
  } else {
    std::string message = "unknown scene kind '";
    message += kind;
    message += "' (city, sphere, torus, mesh)";
    throw std::invalid_argument(message);
  }
  b.faces = count_faces(b.scene);
  b.detail = detail;
  return b;
}

// Peak resident set size of this process in bytes (VmHWM in /proc/self/status; 0 if unavailable).
inline std::size_t peak_rss_bytes() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stoul(line.substr(6)) * 1024;
  return 0;
}

}  // namespace hlr::bench
