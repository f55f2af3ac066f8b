// Near-degenerate meshes (tracker issue 42) against the exact oracle, which decides every sample in
// rationals where the tolerant ray caster would call it ambiguous and skip it:
//   - pancake tetrahedra on a sliver base, their sides folded 10° down to 0.001° onto the base (and so
//     170° to 179.999° against each other);
//   - an open sheet with a sliver flap on its border, folded on by 170° to 179.999° and folded back over
//     the sheet to within 10° down to 0.001°;
//   - two triangles crossing at 1° down to 10⁻⁶°;
//   - twin triangles overlapping 10⁻³ down to 10⁻¹² of their size apart (the back one's edges are hidden
//     where the front one covers them, however close);
//   - an edge passing a corner 10⁻³ down to 10⁻¹² beside it, on it and across it, seen from above;
//   - all of them, and a triangulated sphere, with every coordinate moved by one ulp at random.
// Each from random views; no sample of the drawing may differ from the oracle.
//   hlr_core_tests --gtest_filter='NearDegenerateMesh*'
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/camera/lookat_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "stdlib/generators.hpp"
#include "tests/support/exact_oracle.hpp"
#include "tests/support/mesh_views.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::test {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

struct Mesh {
  std::vector<Point3> vertices;
  std::vector<std::vector<VertexIndex>> faces;
  std::size_t split = 0;  // if set, faces from this one on are a second object
};

// The objects of a mesh: one, or two at its split, each with only the vertices its faces use.
Scene scene_of(const Mesh& mesh) {
  Scene scene;
  const std::size_t end = mesh.split ? mesh.split : mesh.faces.size();
  for (const auto& [begin, stop] : {std::pair{std::size_t{0}, end}, std::pair{end, mesh.faces.size()}}) {
    if (begin == stop) continue;
    std::vector<Point3> vertices;
    std::vector<std::vector<VertexIndex>> faces;
    constexpr VertexIndex kUnused = ~VertexIndex{0};
    std::vector<VertexIndex> index(mesh.vertices.size(), kUnused);
    for (std::size_t f = begin; f < stop; ++f) {
      faces.emplace_back();
      for (VertexIndex v : mesh.faces[f]) {
        if (index[v] == kUnused)
          index[v] = static_cast<VertexIndex>(vertices.size()), vertices.push_back(mesh.vertices[v]);
        faces.back().push_back(index[v]);
      }
    }
    scene.objects.push_back({"mesh", std::make_shared<const Solid>(mesh_solid(vertices, faces))});
  }
  return scene;
}

// A tetrahedron on the sliver triangle (0,0,0), (1,0,0), (0.5,0.05,0) whose apex stands over the base's
// centroid so that the side over the long edge leans `fold` radians off the base.
Mesh pancake(double fold) {
  const double w = 0.05;
  const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0.5, w, 0};
  const Point3 d{0.5, w / 3, (w / 3) * std::tan(fold)};
  return {{a, b, c, d}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}};
}

Vector3 rotated(Vector3 v, Vector3 axis, double angle) {  // Rodrigues, axis of unit length
  return std::cos(angle) * v + std::sin(angle) * cross(axis, v) + (1 - std::cos(angle)) * dot(axis, v) * axis;
}

// A gently curved open 4 × 4 sheet of triangles, and on the border edge from (1/3, 0) to (2/3, 0) a flap
// 1/100 as wide as long, at `dihedral` radians to the sheet's triangle there (π: flat on from it; near
// 0: folded back over it).
Mesh sheet_with_flap(double dihedral) {
  constexpr int kN = 4;
  Mesh m;
  auto height = [](double x, double y) { return 0.08 * std::sin(2.1 * x + 0.4) * std::cos(1.7 * y - 0.3); };
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const double x = i / (kN - 1.0), y = j / (kN - 1.0);
      m.vertices.push_back({x, y, height(x, y)});
    }
  auto at = [](int i, int j) { return static_cast<VertexIndex>(j * kN + i); };
  for (int j = 0; j + 1 < kN; ++j)
    for (int i = 0; i + 1 < kN; ++i) {
      m.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  // The sheet's triangle (1,0), (2,0), (2,1) runs 1 → 2 along the border edge; the flap runs 2 → 1.
  const Point3 u = m.vertices[at(1, 0)], v = m.vertices[at(2, 0)], q = m.vertices[at(2, 1)];
  const Vector3 e = normalize(v - u);
  Vector3 inward = (q - u) - dot(q - u, e) * e;
  inward = normalize(inward);
  const Vector3 dir = rotated(-inward, e, std::numbers::pi - dihedral);
  const double h = 0.01 * distance(u, v);
  // The flap's apex off the edge's middle, rotated either way round: both are folds of that dihedral.
  m.vertices.push_back(lerp(u, v, 0.5) + h * dir);
  m.faces.push_back({at(2, 0), at(1, 0), static_cast<VertexIndex>(kN * kN)});
  return m;
}

// Two triangles crossing at `angle` radians along the line y = 0.1 of the first (z = 0), as one open mesh.
Mesh grazing_pair(double angle) {
  Mesh m;
  m.vertices = {{-1, -0.8, 0}, {1, -0.7, 0}, {0.1, 1, 0}};
  const Point3 pivot{0, 0.1, 0};
  const Vector3 axis{1, 0, 0};
  for (Point3 p : {Point3{-0.9, -0.5, 0}, Point3{0.8, -0.6, 0}, Point3{-0.2, 0.9, 0}})
    m.vertices.push_back(pivot + rotated(p - pivot, axis, angle) + Vector3{0, 0, 0});
  m.faces = {{0, 1, 2}, {3, 4, 5}};
  return m;
}

// Twin triangles, the second a copy of the first moved `gap` (× its size) along the normal and shifted
// sideways so that each covers part of the other.
Mesh twins(double gap, double shift = 1) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0.1, 0}, {0.3, 0.9, 0}};
  for (int k = 0; k < 3; ++k) m.vertices.push_back(m.vertices[k] + Vector3{0.25 * shift, 0.15 * shift, gap});
  m.faces = {{0, 1, 2}, {3, 4, 5}};
  m.split = 1;  // two objects: as one mesh, corners this close would be one vertex
  return m;
}

// A triangle and, across it in front, a thin triangle whose edge passes `miss` (× size) beside the first
// triangle's corner, in the picture of a view straight down — and from other views near it.
Mesh grazing_corner(double miss) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.8, 0}};
  // The front triangle's edge runs along x = 1 + miss, above the corner (1, 0, 0).
  m.vertices.push_back({1 + miss, -0.5, 0.3});
  m.vertices.push_back({1 + miss, 0.5, 0.3});
  m.vertices.push_back({1.6, 0, 0.3});
  m.faces = {{0, 1, 2}, {3, 5, 4}};
  return m;
}

// Every coordinate moved by one ulp up, down or not at all.
Mesh nudged(Mesh m, Rng& r) {
  auto nudge = [&](double x) {
    const int k = r.integer(0, 2);
    return k == 0 ? x : std::nextafter(x, k == 1 ? 1e300 : -1e300);
  };
  for (Point3& p : m.vertices) p = {nudge(p.x), nudge(p.y), nudge(p.z)};
  return m;
}

struct Tally {
  int views = 0, failed = 0;
  std::size_t samples = 0, visible = 0, ambiguous = 0, crossings_visible = 0;
};

// `count` random views of the mesh, each checked against the exact oracle.
Tally check_views(const Mesh& mesh, Point3 center, double size, unsigned seed, int count,
                  const std::string& what) {
  Tally t;
  const Scene scene = scene_of(mesh);
  Rng r(seed);
  for (int n = 0; n < count; ++n) {
    const Camera camera = random_view(r, center, size, n);
    const FrameResult result = render_frame(scene, camera);
    const ExactReport report = check_exact(scene, camera, result);
    ++t.views;
    t.samples += report.drawn_samples + report.edge_samples + report.crossing_samples;
    t.visible += report.edge_visible + report.crossing_visible;
    t.crossings_visible += report.crossing_visible;
    t.ambiguous += report.ambiguous;
    if (!report.ok()) {
      ++t.failed;
      ADD_FAILURE() << what << ", view " << n << " of seed " << seed << ":\n" << report.summary();
    }
  }
  return t;
}

TEST(NearDegenerateMesh, PancakesFoldedFlat) {
  const double folds[] = {10, 1, 0.1, 0.01, 0.001};
  unsigned seed = 1;
  for (double fold : folds) {
    const Mesh m = pancake(fold * kDegree);
    const Tally t =
        check_views(m, {0.5, 0.02, 0}, 0.6, seed++, 20, "pancake folded " + std::to_string(fold) + "°");
    EXPECT_EQ(t.failed, 0);
    EXPECT_GT(t.visible, 1000u);
  }
}

TEST(NearDegenerateMesh, SliverFlapFoldedOnAndBack) {
  const double folds[] = {10, 5, 1, 0.5, 0.1, 0.01, 0.001};
  unsigned seed = 100;
  for (double fold : folds)
    for (const bool back : {false, true}) {
      const double dihedral = (back ? fold : 180 - fold) * kDegree;
      const Mesh m = sheet_with_flap(dihedral);
      const Tally t = check_views(m, {0.5, 0.5, 0}, 0.8, seed++, 10,
                                  std::string(back ? "flap folded back to " : "flap folded on by ") +
                                      std::to_string(back ? fold : 180 - fold) + "°");
      EXPECT_EQ(t.failed, 0);
    }
}

TEST(NearDegenerateMesh, TrianglesCrossingAtGrazingAngles) {
  const double angles[] = {1, 0.01, 1e-4, 1e-6};
  unsigned seed = 200;
  for (double angle : angles) {
    const Tally t = check_views(grazing_pair(angle * kDegree), {0, 0, 0}, 1.2, seed++, 25,
                                "triangles crossing at " + std::to_string(angle) + "°");
    EXPECT_EQ(t.failed, 0);
    EXPECT_GT(t.crossings_visible, 100u) << "the crossing should be seen in most views";
  }
}

TEST(NearDegenerateMesh, NearCoplanarTwins) {
  const double gaps[] = {1e-3, 1e-6, 1e-9, 1e-12};
  unsigned seed = 400;
  for (double gap : gaps) {
    const Tally t =
        check_views(twins(gap), {0.6, 0.5, 0}, 1, seed++, 25, "twins " + std::to_string(gap) + " apart");
    EXPECT_EQ(t.failed, 0);
    // Stacked exactly: the back one's edges lie a hair inside or outside the front one's in the picture.
    const Tally stacked = check_views(twins(gap, 0), {0.5, 0.4, 0}, 1, seed++, 25,
                                      "stacked twins " + std::to_string(gap) + " apart");
    EXPECT_EQ(stacked.failed, 0);
  }
}

TEST(NearDegenerateMesh, EdgesGrazingACorner) {
  const double misses[] = {1e-3, 1e-6, 1e-9, 1e-12, 0, -1e-12, -1e-9};
  unsigned seed = 500;
  for (double miss : misses) {
    // Views from near straight above, where the front edge passes the corner closest in the picture.
    Scene scene;
    const Mesh m = grazing_corner(miss);
    scene.objects.push_back({"corner", std::make_shared<const Solid>(mesh_solid(m.vertices, m.faces))});
    Rng r(seed++);
    for (int n = 0; n < 12; ++n) {
      // Straight above the corner (the front edge's picture passes it at `miss`), then tilted a little.
      const Point3 target{1, 0, 0};
      const Vector3 off = n == 0 ? Vector3{0, 0, 1} : Vector3{r(-0.02, 0.02), r(-0.02, 0.02), 1};
      const Camera camera = lookat_camera(LookatParameters{target + 3 * off, target, {0, 1, 0}, 40, 0, 0});
      const FrameResult result = render_frame(scene, camera);
      const ExactReport report = check_exact(scene, camera, result);
      EXPECT_TRUE(report.ok()) << "miss " << miss << ", view " << n << ":\n" << report.summary();
    }
  }
}

// A smooth sphere (every edge drawn only on the contour) seen with the eye in the plane of one of its
// triangles, or 1e-10 or 1e-13 of the distance off it on either side: whether that triangle faces the eye
// decides which of its edges are on the contour — exactly, or the outline has a gap one face long.
TEST(NearDegenerateMesh, ContourThroughATriangleSeenEdgeOn) {
  const Solid ball = stdlib::sphere({0, 0, 0}, 1, 16, 9, 0);
  const Solid smooth = mesh_solid(ball.vertices, triangles_of(ball), 60);
  Scene scene;
  scene.objects.push_back({"ball", std::make_shared<const Solid>(smooth)});
  Rng r(600);
  int views = 0, contour = 0;
  for (int n = 0; n < 60; ++n) {
    const FaceIndex f = static_cast<FaceIndex>(r.integer(0, static_cast<int>(smooth.faces.size()) - 1));
    const auto& ring = smooth.faces[f].rings[0].vertices;
    const Point3 a = smooth.vertices[ring[0]], b = smooth.vertices[ring[1]], c = smooth.vertices[ring[2]];
    const Vector3 normal = normalize(cross(b - a, c - a));
    const Point3 centroid = a + (1.0 / 3) * ((b - a) + (c - a));
    const Vector3 along = normalize(cross(normal, r.direction()));  // in the triangle's plane
    const double offsets[] = {0, 1e-10, -1e-10, 1e-13, -1e-13};
    const double distance_away = r(3, 5);
    const Point3 eye = centroid + distance_away * along + offsets[n % 5] * distance_away * normal;
    const Camera camera = lookat_camera(LookatParameters{eye, {0, 0, 0}, normal, 40, 0, 0});
    const FrameResult result = render_frame(scene, camera);
    const ExactReport report = check_exact(scene, camera, result);
    EXPECT_TRUE(report.ok()) << "view " << n << " (face " << f << ", offset " << offsets[n % 5] << "):\n"
                             << report.summary();
    ++views;
    contour += report.edge_visible > 0;
  }
  EXPECT_EQ(views, 60);
  EXPECT_EQ(contour, 60) << "every view should see the contour";
}

TEST(NearDegenerateMesh, OneUlpFromEverything) {
  Rng r(300);
  std::vector<std::pair<std::string, Mesh>> meshes = {{"pancake", pancake(0.01 * kDegree)},
                                                      {"flap", sheet_with_flap(0.01 * kDegree)},
                                                      {"grazing", grazing_pair(1e-4 * kDegree)},
                                                      {"twins", twins(1e-12)}};
  const Solid sphere = stdlib::sphere({0, 0, 0}, 1, 10, 6, 0);
  meshes.push_back({"sphere", {sphere.vertices, triangles_of(sphere)}});
  unsigned seed = 300;
  for (const auto& [name, mesh] : meshes)
    for (int k = 0; k < 4; ++k) {
      const Tally t = check_views(nudged(mesh, r), {0.3, 0.3, 0}, 1.2, seed++, 6, name + " moved by one ulp");
      EXPECT_EQ(t.failed, 0);
    }
}

}  // namespace
}  // namespace hlr::test
