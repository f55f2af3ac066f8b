// The Sketch peer (Debian `sketch`, Eugene Ressler's 3-D scene compiler for PSTricks/TikZ): the solid's
// faces as Sketch polygons seen through the same view, timed through the `sketch` command. Sketch hides
// by ordering whole polygons (depth sort with splitting, or a BSP tree with -b) and paints them opaque;
// it computes no visible edges, so there is no visible length to compare.
#pragma once

#include <filesystem>
#include <optional>

#include "core/camera/camera.hpp"
#include "core/solid/solid.hpp"

namespace hlr::peers {

// Writes `path`: one `polygon` per face (outer ring), `view(eye, eye + forward, [up]) then
// perspective(focal)` (or `scale(focal)` for a parallel view) — Sketch's picture is then ours. Throws
// for a camera with a picture offset.
void write_sketch_input(const Solid& solid, const Camera& camera, const std::filesystem::path& path);

struct SketchResult {
  double seconds = 0;  // median wall time of the whole `sketch` process (parse, hide, write)
  bool ok = false;     // false: it failed or ran past the time limit
  bool timed_out = false;
};

// Runs `sketch [-b] -o OUT IN` `runs` times (stops after a run that fails or exceeds limit_s seconds).
SketchResult run_sketch(const std::filesystem::path& input, bool bsp, int runs, double limit_s);

// Whether `sketch` is on the PATH.
bool sketch_available();

}  // namespace hlr::peers
