// Real meshes against the ray-casting oracle (tests/support/ray_caster_checks.hpp), from random views as
// tracker issue 42 measured them: the eye 2–3.5 bounding-box diagonals from the centre in a random
// direction, fov 25–60°. Prints one line per view: what was drawn and what the oracle disputes — drawn
// pieces it finds hidden (edges, intersection lines), edges and intersection lines it finds missing.
//   build/bench/oracle_views [--views N] [--seed S] [--crease DEG] [--verbose] FILE...
// A measurement, not a test: its figures go to bench/README.md.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "core/camera/lookat_camera.hpp"
#include "core/geometry/box3.hpp"
#include "core/hlr/render_frame.hpp"
#include "stdlib/mesh_import.hpp"
#include "tests/support/ray_caster_checks.hpp"
#include "tests/support/seeded_rng.hpp"

namespace {

using namespace hlr;

struct Tally {
  int hidden_edge = 0, hidden_intersection = 0, missing_edge = 0, missing_intersection = 0, other = 0;
  int total() const {
    return hidden_edge + hidden_intersection + missing_edge + missing_intersection + other;
  }
};

Tally tally(const std::vector<std::string>& failures) {
  Tally t;
  for (const std::string& f : failures) {
    if (f.find("missing intersection") != std::string::npos) {
      ++t.missing_intersection;
    } else if (f.find("missing:") != std::string::npos) {
      ++t.missing_edge;
    } else if (f.find("is hidden") != std::string::npos) {
      (f.find("intersection piece") != std::string::npos ? t.hidden_intersection : t.hidden_edge)++;
    } else {
      ++t.other;
    }
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  int views = 2;
  unsigned seed = 42;
  double crease = 0;
  bool verbose = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--views" && i + 1 < argc) {
      views = std::atoi(argv[++i]);
    } else if (a == "--seed" && i + 1 < argc) {
      seed = static_cast<unsigned>(std::atoi(argv[++i]));
    } else if (a == "--crease" && i + 1 < argc) {
      crease = std::atof(argv[++i]);
    } else if (a == "--verbose") {
      verbose = true;
    } else {
      files.push_back(a);
    }
  }
  int meshes = 0, checked = 0, disputed = 0;
  Tally all;
  for (const std::string& file : files) {
    std::shared_ptr<const Solid> solid;
    try {
      stdlib::MeshImportOptions options;
      options.crease_angle_deg = crease;
      solid = std::make_shared<const Solid>(stdlib::import_mesh(file, options).solid);
    } catch (const std::exception& e) {
      std::printf("%s: not imported: %s\n", file.c_str(), e.what());
      continue;
    }
    ++meshes;
    Box3 box;
    for (Point3 p : solid->vertices) box.include(p);
    const Point3 center = lerp(box.lo, box.hi, 0.5);
    const double diagonal = distance(box.lo, box.hi);
    Scene scene;
    scene.objects.push_back({"mesh", solid});
    test::Rng rng(seed);
    for (int v = 0; v < views; ++v) {
      const Point3 eye = center + rng(2, 3.5) * diagonal * rng.direction();
      const Vector3 up = std::abs(normalize(center - eye).z) > 0.99 ? Vector3{0, 1, 0} : Vector3{0, 0, 1};
      const Camera camera = lookat_camera(LookatParameters{eye, center, up, rng(25, 60), 0, 0});
      const FrameResult result = render_frame(scene, camera);
      test::CheckOptions check;
      check.max_failures = 100000;
      const test::CheckReport report = test::check_frame(scene, camera, result, check);
      const Tally t = tally(report.failures);
      ++checked;
      disputed += t.total() > 0;
      all.hidden_edge += t.hidden_edge, all.hidden_intersection += t.hidden_intersection;
      all.missing_edge += t.missing_edge, all.missing_intersection += t.missing_intersection;
      all.other += t.other;
      std::printf(
          "%s view %d: %zu faces%s, %zu self-crossing pieces, %zu drawn; disputed: hidden edge %d, "
          "hidden intersection %d, missing edge %d, missing intersection %d, other %d\n",
          file.c_str(), v, solid->faces.size(), solid->closed ? " closed" : "",
          solid->self_crossings().size(), result.segments.size(), t.hidden_edge, t.hidden_intersection,
          t.missing_edge, t.missing_intersection, t.other);
      if (verbose)
        for (std::size_t i = 0; i < report.failures.size() && i < 5; ++i)
          std::printf("    %s\n", report.failures[i].c_str());
    }
  }
  std::printf(
      "%d meshes, %d views, %d disputed; hidden edge %d, hidden intersection %d, missing edge %d, "
      "missing intersection %d, other %d\n",
      meshes, checked, disputed, all.hidden_edge, all.hidden_intersection, all.missing_edge,
      all.missing_intersection, all.other);
  return 0;
}
