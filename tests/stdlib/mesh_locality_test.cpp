// Spatial order of large imported meshes (stdlib/mesh_locality.cpp, mesh_build.cpp): the orders themselves
// on cases worked out by hand, and an imported shuffled torus against the same triangles built directly by
// SolidBuilder in the file's order — the same solid but for numbering, drawing the same, laid out along the
// space, and with the file's own face numbers in its messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "core/camera/lookat_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "core/solid/solid_builder.hpp"
#include "stdlib/mesh_detail.hpp"
#include "stdlib/mesh_import.hpp"

namespace hlr::stdlib {
namespace {

using mesh_detail::faces_by_least_vertex;
using mesh_detail::kSpatialOrderFaces;
using mesh_detail::morton_order;

TEST(MortonOrder, CubeCornersFollowTheCurve) {
  // The corners listed backwards; the curve visits x's bit first, then y's, then z's.
  std::vector<Point3> corners;
  for (int k = 7; k >= 0; --k) corners.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
  EXPECT_EQ(morton_order(corners), (std::vector<std::uint32_t>{7, 6, 5, 4, 3, 2, 1, 0}));
}

TEST(MortonOrder, QuadrantsBeforeTheirInsidesAndTiesKeepTheirOrder) {
  // On a 4 × 4 grid in x and y (z flat): the lower-left quadrant's four cells come before any other.
  const std::vector<Point3> points = {{3, 3, 0}, {0, 1, 0}, {1, 0, 0}, {2, 0, 0},
                                      {0, 0, 0}, {1, 1, 0}, {0, 2, 0}, {0, 0, 0}};
  // Cells (1023 / 3 per unit): (0,0) for points 4 and 7 (in that order), (341,0) for 2, (0,341) for 1,
  // (341,341) for 5; then (682,0) for 3, (0,682) for 6 and (1023,1023) for 0.
  EXPECT_EQ(morton_order(points), (std::vector<std::uint32_t>{4, 7, 2, 1, 5, 3, 6, 0}));
}

TEST(MortonOrder, DegenerateAndNonFinitePointsStillGiveAPermutation) {
  const std::vector<Point3> same(5, Point3{2, 2, 2});
  EXPECT_EQ(morton_order(same), (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  std::vector<std::uint32_t> order =
      morton_order(std::vector<Point3>{{0, 0, 0}, {nan, 1, 1}, {inf, 0, -inf}});
  std::sort(order.begin(), order.end());
  EXPECT_EQ(order, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_TRUE(morton_order(std::vector<Point3>{}).empty());
}

TEST(FacesByLeastVertex, StableCountingOrder) {
  // Faces (5 4 6), (0 1 2 3), (4 7 5), (2 0 9): least vertices 4, 0, 4, 0.
  const std::vector<std::uint32_t> vertices = {5, 4, 6, 0, 1, 2, 3, 4, 7, 5, 2, 0, 9};
  const std::vector<std::size_t> ends = {3, 7, 10, 13};
  EXPECT_EQ(faces_by_least_vertex(vertices, ends, 10), (std::vector<std::uint32_t>{1, 3, 0, 2}));
}

// Large enough to go by parts: the order is the Morton order computed here one point at a time (bits
// interleaved one by one, a stable sort), with non-finite coordinates among the points.
TEST(MortonOrder, ManyPointsByPartsAsOneByOne) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> coordinate(-5, 7);
  std::vector<Point3> points(100'000);
  for (Point3& p : points) p = {coordinate(rng), coordinate(rng) * 0.01, coordinate(rng)};
  points[77'777].y = std::numeric_limits<double>::quiet_NaN();
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const Point3& p : points)
    for (int a = 0; a < 3; ++a)
      if (std::isfinite(p[a])) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  std::vector<std::uint64_t> code(points.size(), 0);
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      const double t = (points[i][a] - lo[a]) * (1023.0 / (hi[a] - lo[a]));
      const auto cell = t >= 0 ? static_cast<std::uint64_t>(std::min(t, 1023.0)) : 0;  // NaN: 0
      for (int bit = 0; bit < 10; ++bit) code[i] |= ((cell >> bit) & 1) << (3 * bit + a);
    }
  std::vector<std::uint32_t> expected(points.size());
  std::iota(expected.begin(), expected.end(), 0u);
  std::stable_sort(expected.begin(), expected.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return code[a] < code[b]; });
  EXPECT_EQ(morton_order(points), expected);
}

// Faces of three to five vertices put in the order of their least vertex, by parts: as a stable sort of
// the faces by it, their vertices copied after each other.
TEST(FacesByLeastVertex, ManyFacesOrderedByPartsAsBySorting) {
  std::mt19937_64 rng(7);
  std::vector<std::uint32_t> vertices;
  std::vector<std::size_t> ends;
  for (int f = 0; f < 60'000; ++f) {
    const int size = 3 + static_cast<int>(rng() % 3);
    for (int k = 0; k < size; ++k) vertices.push_back(static_cast<std::uint32_t>(rng() % 20'000));
    ends.push_back(vertices.size());
  }
  auto face = [&](std::size_t f) {
    return std::vector<std::uint32_t>(
        vertices.begin() + static_cast<std::ptrdiff_t>(f == 0 ? 0 : ends[f - 1]),
        vertices.begin() + static_cast<std::ptrdiff_t>(ends[f]));
  };
  std::vector<std::size_t> order(ends.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto fa = face(a), fb = face(b);
    return *std::min_element(fa.begin(), fa.end()) < *std::min_element(fb.begin(), fb.end());
  });
  std::vector<std::uint32_t> expected;
  std::vector<std::size_t> expected_ends;
  for (std::size_t f : order) {
    const auto ring = face(f);
    expected.insert(expected.end(), ring.begin(), ring.end());
    expected_ends.push_back(expected.size());
  }
  std::vector<std::uint32_t> ordered;
  std::vector<std::size_t> ordered_ends;
  mesh_detail::order_faces_by_least_vertex(vertices, ends, 20'000, ordered, ordered_ends);
  EXPECT_EQ(ordered, expected);
  EXPECT_EQ(ordered_ends, expected_ends);
}

// A torus of nu × nv quads split into triangles, outward, with its vertices and faces shuffled (fixed seed).
struct Triangles {
  std::vector<Point3> vertices;
  std::vector<std::array<std::uint32_t, 3>> faces;
};

Triangles shuffled_torus(int nu, int nv) {
  Triangles t;
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>(((i + nu) % nu) * nv + (j + nv) % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * std::numbers::pi * i / nu, v = 2 * std::numbers::pi * j / nv;
      t.vertices.push_back({(3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v)});
      t.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  std::mt19937 rng(20261207);
  std::vector<std::uint32_t> place(t.vertices.size());
  std::iota(place.begin(), place.end(), 0u);
  std::shuffle(place.begin(), place.end(), rng);
  std::vector<Point3> moved(t.vertices.size());
  for (std::size_t v = 0; v < place.size(); ++v) moved[place[v]] = t.vertices[v];
  t.vertices = moved;
  for (auto& f : t.faces)
    for (std::uint32_t& v : f) v = place[v];
  std::shuffle(t.faces.begin(), t.faces.end(), rng);
  return t;
}

std::string off_text(const Triangles& t) {
  std::string s = "OFF\n" + std::to_string(t.vertices.size()) + " " + std::to_string(t.faces.size()) + " 0\n";
  char line[128];
  for (const Point3& p : t.vertices) {
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
    s += line;
  }
  for (const auto& f : t.faces)
    s += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
  return s;
}

using Key = std::array<double, 3>;
Key key_of(Point3 p) { return {p.x, p.y, p.z}; }

// Faces as cycles of positions, each started at its least point (orientation kept).
std::multiset<std::vector<Key>> face_cycles(const Solid& s) {
  std::multiset<std::vector<Key>> out;
  for (const Face& f : s.faces) {
    std::vector<Key> cycle;
    for (VertexIndex v : f.rings[0].vertices) cycle.push_back(key_of(s.vertices[v]));
    std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
    out.insert(cycle);
  }
  return out;
}

// Edges by their ends' positions: kind, concavity, and the cycles of the faces on each side.
std::map<std::pair<Key, Key>, std::string> edge_table(const Solid& s) {
  std::map<std::pair<Key, Key>, std::string> out;
  for (const SolidEdge& e : s.edges) {
    Key a = key_of(s.vertices[e.v0]), b = key_of(s.vertices[e.v1]);
    const bool swapped = b < a;
    if (swapped) std::swap(a, b);
    auto side = [&](FaceIndex f) {
      std::string text;
      for (VertexIndex v : s.faces[static_cast<std::size_t>(f)].rings[0].vertices) {
        const Point3 p = s.vertices[v];
        text += std::to_string(p.x) + "," + std::to_string(p.y) + "," + std::to_string(p.z) + ";";
      }
      return text;
    };
    const FaceIndex first = swapped ? e.right : e.left, second = swapped ? e.left : e.right;
    out[{a, b}] = std::to_string(static_cast<int>(e.kind)) + (e.concave ? "c " : " ") + side(first) + " | " +
                  side(second);
  }
  return out;
}

TEST(SpatialImport, ShuffledTorusIsTheSameSolidLaidOutAlongTheSpace) {
  const Triangles t = shuffled_torus(128, 40);  // 10 240 triangles
  ASSERT_GE(t.faces.size(), kSpatialOrderFaces);
  MeshImportOptions options;
  options.crease_angle_deg = 5;  // round the tube (9° a step) creases, along it (2.8°) smooth
  const ImportedMesh imported = import_off(off_text(t), "torus.off", options);
  EXPECT_TRUE(imported.warnings.empty());

  // The same triangles straight into SolidBuilder, in the file's order.
  SolidBuildOptions build_options;
  build_options.crease_angle_deg = 5;
  SolidBuilder builder(build_options);
  for (const Point3& p : t.vertices) builder.add_vertex(p);
  for (const auto& f : t.faces) builder.add_indexed_polygon(f);
  const SolidBuildResult direct = builder.build();
  ASSERT_TRUE(direct.ok());
  EXPECT_TRUE(direct.diagnostics.empty());

  const Solid &a = imported.solid, &b = *direct.solid;
  EXPECT_EQ(a.closed, b.closed);
  EXPECT_TRUE(a.closed);
  EXPECT_EQ(a.folded, b.folded);
  std::vector<Key> va, vb;
  for (Point3 p : a.vertices) va.push_back(key_of(p));
  for (Point3 p : b.vertices) vb.push_back(key_of(p));
  EXPECT_NE(va, vb);  // renumbered
  std::sort(va.begin(), va.end());
  std::sort(vb.begin(), vb.end());
  EXPECT_EQ(va, vb);
  EXPECT_EQ(face_cycles(a), face_cycles(b));
  EXPECT_EQ(edge_table(a), edge_table(b));
  auto count = [&](EdgeKind kind) {
    return std::count_if(a.edges.begin(), a.edges.end(), [&](const SolidEdge& e) { return e.kind == kind; });
  };
  EXPECT_GT(count(EdgeKind::Feature), 1000);
  EXPECT_GT(count(EdgeKind::Smooth), 1000);
  for (std::size_t f = 0; f < a.faces.size(); ++f) {  // planes follow their faces
    const Vector3 n = newell_normal(a.vertices, a.faces[f].rings[0]);
    EXPECT_NEAR(dot(n / length(n), a.planes[f].normal), 1.0, 1e-12);
  }

  // Laid out along the space: consecutive vertices, and the first vertices of consecutive faces, lie far
  // nearer each other than in the shuffled file (whose neighbours are a random pair, ~4.5 apart on average).
  auto mean_step = [](const std::vector<Point3>& points) {
    double sum = 0;
    for (std::size_t i = 1; i < points.size(); ++i) sum += distance(points[i - 1], points[i]);
    return sum / static_cast<double>(points.size() - 1);
  };
  auto face_starts = [](const Solid& s) {
    std::vector<Point3> out;
    for (const Face& f : s.faces) out.push_back(s.vertices[f.rings[0].vertices[0]]);
    return out;
  };
  EXPECT_LT(mean_step(a.vertices), 0.2 * mean_step(b.vertices));
  EXPECT_LT(mean_step(face_starts(a)), 0.2 * mean_step(face_starts(b)));

  // And it draws the same: the visible pieces of both, from a camera that sees the hole and the inner ring
  // over the outer, as sets of end points (rounded far below the pieces' size, far above rounding).
  const Camera camera = lookat_camera(LookatParameters{{9, -7, 6}, {0, 0, 0}, {0, 0, 1}, 35, 0, 0});
  auto drawing = [&](const Solid& solid) {
    Scene scene;
    scene.objects.push_back({"torus", solid});
    std::set<std::array<long long, 6>> pieces;
    for (const VisibleSegment& s : render_frame(scene, camera).segments) {
      std::array<long long, 3> p{}, q{};
      for (int k = 0; k < 3; ++k) p[k] = std::llround(s.p0[k] * 1e7), q[k] = std::llround(s.p1[k] * 1e7);
      if (q < p) std::swap(p, q);
      pieces.insert({p[0], p[1], p[2], q[0], q[1], q[2]});
    }
    return pieces;
  };
  const auto seen = drawing(a);
  EXPECT_GT(seen.size(), 2000u);
  EXPECT_EQ(seen, drawing(b));
}

TEST(SpatialImport, AMeshWithProblemsIsReportedInTheFilesOwnNumbers) {
  // The same torus with one triangle turned over: the builder's warning names that face by its number in
  // the file and points at its line, as for a mesh in file order.
  Triangles t = shuffled_torus(128, 40);
  const std::size_t turned = 5000;
  std::swap(t.faces[turned][1], t.faces[turned][2]);
  const ImportedMesh imported = import_off(off_text(t), "torus.off");
  ASSERT_EQ(imported.warnings.size(), 1u);
  const MeshProblem& p = imported.warnings[0];
  EXPECT_NE(p.message.find("face " + std::to_string(turned + 1)), std::string::npos) << p.to_string();
  EXPECT_EQ(p.line, static_cast<int>(3 + t.vertices.size() + turned)) << p.to_string();
  // And it is reversed back: every face outward again, as in the unturned file.
  Triangles fixed = t;
  std::swap(fixed.faces[turned][1], fixed.faces[turned][2]);
  EXPECT_EQ(face_cycles(imported.solid), face_cycles(import_off(off_text(fixed), "fixed.off").solid));
}

}  // namespace
}  // namespace hlr::stdlib
