// Seams: an edge whose picture runs exactly along the shared edge of two neighbouring faces that both hide
// it (a triangulated wall's undrawn diagonal, a mesh ridge) is hidden; each face alone would only see it on
// its boundary.
#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "core/solid/solid_builder.hpp"

namespace hlr {
namespace {

// A unit square at z = 1 split along its diagonal (0,0)–(1,1) into two triangles (an open surface whose
// diagonal is Flat, so not drawn), and a free line at z = 0 from (−1,−1) to (2,2), right under the diagonal.
Scene wall_over_line() {
  SolidBuilder wall;
  wall.add_vertex("a", {0, 0, 1});
  wall.add_vertex("b", {1, 0, 1});
  wall.add_vertex("c", {1, 1, 1});
  wall.add_vertex("d", {0, 1, 1});
  wall.add_face({"a", "b", "c"});
  wall.add_face({"a", "c", "d"});
  SolidBuilder line;
  line.add_vertex("p", {-1, -1, 0});
  line.add_vertex("q", {2, 2, 0});
  line.add_line("p", "q");
  Scene scene;
  scene.objects.push_back({"wall", *wall.build().solid});
  scene.objects.push_back({"line", *line.build().solid});
  return scene;
}

TEST(SeamOcclusion, LineUnderATriangulatedWallsDiagonalIsHiddenWhereTheWallIs) {
  const Scene scene = wall_over_line();
  int flat = 0;
  for (const SolidEdge& e : scene.objects[0].solid->edges) flat += e.kind == EdgeKind::Flat;
  ASSERT_EQ(flat, 1);
  // Straight down: the line's picture is the diagonal's. Perspective from above the wall's centre too.
  const Camera cameras[] = {ortho_camera({{0.5, 0.5, 10}, {0.5, 0.5, 0}, {0, 1, 0}, 4, 0}),
                            lookat_camera({{0.5, 0.5, 10}, {0.5, 0.5, 0}, {0, 1, 0}, 60, 0, 0})};
  for (const Camera& camera : cameras) {
    SCOPED_TRACE(camera.kind);
    const FrameResult r = render_frame(scene, camera);
    double line_visible = 0;
    for (const VisibleSegment& s : r.segments) {
      if (s.object != 1) continue;
      line_visible += distance(s.p0, s.p1);
      // Every visible piece lies outside the wall's shadow on the line: x ∉ (0, 1) in ortho; in perspective
      // the wall's shadow on z = 0 is the square scaled by 10/9 about (0.5, 0.5).
      const double lo = camera.kind == "ortho" ? 0.0 : 0.5 - 0.5 * 10.0 / 9.0;
      const double hi = camera.kind == "ortho" ? 1.0 : 0.5 + 0.5 * 10.0 / 9.0;
      for (const Point3 p : {s.p0, s.p1, lerp(s.p0, s.p1, 0.5)})
        EXPECT_FALSE(p.x > lo + 1e-9 && p.x < hi - 1e-9) << "visible at x = " << p.x;
    }
    const double shadow = camera.kind == "ortho" ? 1.0 : 10.0 / 9.0;
    EXPECT_NEAR(line_visible, std::sqrt(2.0) * (3 - shadow), 1e-9);
  }
}

}  // namespace
}  // namespace hlr
