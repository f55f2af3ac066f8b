// The builder's edge table against a reference written from solid.hpp's contract: every undirected ring
// edge once, numbered in the order the faces (in input order), their rings and their sides first name
// it; its faces are the ones that traverse it; each ring's `edges` names the edge of each side. The
// reference is a map filled face by face. Seeded meshes: tori of triangles and quads with faces and
// vertex numbers shuffled (so first-seen order is far from vertex order), the same with faces left out
// (open), a face with a hole, an edge of three faces (its error names the three), and fans of thousands
// of triangles round one vertex (the lookup table's runs of full slots crowd round it, edge_table.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/solid/solid.hpp"
#include "core/solid/solid_builder.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr {
namespace {

using Rings = std::vector<std::vector<VertexIndex>>;

struct Mesh {
  std::vector<Point3> points;
  std::vector<Rings> faces;
};

// A torus of n × m vertices, quads or pairs of triangles, counter-clockwise seen from outside; vertex
// numbers and face order shuffled by `rng`.
Mesh shuffled_torus(test::Rng& rng, int n, int m, bool quads) {
  Mesh mesh;
  std::vector<VertexIndex> label(static_cast<std::size_t>(n * m));
  for (std::size_t i = 0; i < label.size(); ++i) label[i] = static_cast<VertexIndex>(i);
  for (std::size_t i = label.size(); i > 1; --i) std::swap(label[i - 1], label[rng.engine() % i]);
  mesh.points.resize(label.size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * std::numbers::pi * i / n, v = 2 * std::numbers::pi * j / m;
      mesh.points[label[static_cast<std::size_t>(i * m + j)]] = {
          (3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v)};
    }
  auto at = [&](int i, int j) { return label[static_cast<std::size_t>((i % n) * m + (j % m))]; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const VertexIndex a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (quads) {
        mesh.faces.push_back({{a, b, c, d}});
      } else {
        mesh.faces.push_back({{a, b, c}});
        mesh.faces.push_back({{a, c, d}});
      }
    }
  for (std::size_t i = mesh.faces.size(); i > 1; --i)
    std::swap(mesh.faces[i - 1], mesh.faces[rng.engine() % i]);
  return mesh;
}

std::pair<VertexIndex, VertexIndex> ordered(VertexIndex a, VertexIndex b) {
  return {std::min(a, b), std::max(a, b)};
}

SolidBuildResult build(const Mesh& mesh) {
  SolidBuilder b;
  for (const Point3& p : mesh.points) b.add_vertex(p);
  for (const Rings& rings : mesh.faces) b.add_indexed_face(rings);
  return b.build();
}

// The contract, checked on a solid built from `mesh` (whose faces it keeps in order, and whose windings
// need no repair).
void expect_edges_as_named(const Mesh& mesh, const Solid& solid) {
  std::map<std::pair<VertexIndex, VertexIndex>, std::uint32_t> number;
  std::vector<std::set<FaceIndex>> faces_of;
  std::vector<std::pair<VertexIndex, VertexIndex>> ends;
  ASSERT_EQ(solid.faces.size(), mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const Rings& rings = mesh.faces[f];
    ASSERT_EQ(solid.faces[f].rings.size(), rings.size()) << "face " << f;
    for (std::size_t k = 0; k < rings.size(); ++k) {
      const auto& ring = rings[k];
      ASSERT_EQ(solid.faces[f].rings[k].vertices.size(), ring.size());
      ASSERT_EQ(solid.faces[f].rings[k].edges.size(), ring.size());
      for (std::size_t i = 0; i < ring.size(); ++i) {
        ASSERT_EQ(solid.faces[f].rings[k].vertices[i], ring[i]) << "face " << f << " was changed";
        const VertexIndex a = ring[i], b = ring[(i + 1) % ring.size()];
        const auto key = ordered(a, b);
        const auto [it, fresh] = number.try_emplace(key, static_cast<std::uint32_t>(ends.size()));
        if (fresh) {
          ends.push_back(key);
          faces_of.emplace_back();
        }
        faces_of[it->second].insert(static_cast<FaceIndex>(f));
        EXPECT_EQ(solid.faces[f].rings[k].edges[i], it->second) << "face " << f << " side " << i;
      }
    }
  }
  ASSERT_EQ(solid.edges.size(), ends.size());
  for (std::size_t e = 0; e < ends.size(); ++e) {
    const SolidEdge& edge = solid.edges[e];
    EXPECT_EQ(ordered(edge.v0, edge.v1), ends[e]) << "edge " << e;
    std::set<FaceIndex> faces;
    if (edge.left != kNoFace) faces.insert(edge.left);
    if (edge.right != kNoFace) faces.insert(edge.right);
    EXPECT_EQ(faces, faces_of[e]) << "edge " << e;
  }
}

// Builds `mesh`, which must be valid, and checks the contract on it.
void expect_built_as_named(const Mesh& mesh) {
  const SolidBuildResult result = build(mesh);
  ASSERT_TRUE(result.ok());
  expect_edges_as_named(mesh, *result.solid);
}

TEST(EdgeNumbering, ShuffledClosedMeshesNumberEdgesInFirstSeenOrder) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    test::Rng rng(seed);
    const Mesh mesh =
        shuffled_torus(rng, 20 + static_cast<int>(seed), 9 + static_cast<int>(seed), seed % 2 == 0);
    const SolidBuildResult result = build(mesh);
    ASSERT_TRUE(result.ok()) << "seed " << seed;
    EXPECT_TRUE(result.solid->closed);
    expect_edges_as_named(mesh, *result.solid);
  }
}

TEST(EdgeNumbering, OpenMeshesKeepTheirBorderEdgesOnce) {
  for (unsigned seed = 11; seed <= 14; ++seed) {
    test::Rng rng(seed);
    Mesh mesh = shuffled_torus(rng, 24, 10, false);
    // Every third face left out: borders of one face each.
    Mesh open{mesh.points, {}};
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
      if (f % 3 != 0) open.faces.push_back(mesh.faces[f]);
    const SolidBuildResult result = build(open);
    ASSERT_TRUE(result.ok()) << "seed " << seed;
    EXPECT_FALSE(result.solid->closed);
    expect_edges_as_named(open, *result.solid);
  }
}

TEST(EdgeNumbering, FacesWithHolesNumberTheirHoleEdgesAfterTheOutline) {
  // A square plate with a square hole, above a second plate: two rings, then one.
  Mesh mesh;
  mesh.points = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {1, 1, 0}, {1, 3, 0},
                 {3, 3, 0}, {3, 1, 0}, {0, 0, 1}, {4, 0, 1}, {4, 4, 1}};
  mesh.faces = {{{0, 1, 2, 3}, {4, 5, 6, 7}}, {{8, 9, 10}}};
  expect_built_as_named(mesh);
}

TEST(EdgeNumbering, AnEdgeOfThreeFacesIsReportedWithItsFaces) {
  test::Rng rng(21);
  Mesh mesh = shuffled_torus(rng, 12, 8, false);
  // A fin on the first face's first side: a third face on that edge.
  const VertexIndex a = mesh.faces[0][0][0], b = mesh.faces[0][0][1];
  mesh.points.push_back({9, 9, 9});
  mesh.faces.push_back({{a, b, static_cast<VertexIndex>(mesh.points.size() - 1)}});
  const SolidBuildResult result = build(mesh);
  ASSERT_FALSE(result.ok());
  bool found = false;
  for (const SolidDiagnostic& d : result.diagnostics)
    if (d.code == "non-manifold-edge") {
      found = true;
      EXPECT_NE(d.message.find("is used by 3 faces (1, "), std::string::npos) << d.message;
      EXPECT_NE(d.message.find(", " + std::to_string(mesh.faces.size()) + ")"), std::string::npos)
          << d.message;
    }
  EXPECT_TRUE(found);
}

// A double cone: hubs 0 (top) and 1 (bottom) with `rim` triangles each round a rim of vertices 2 …;
// faces shuffled by `rng`, the rim's numbers shuffled too where `shuffle_rim`.
Mesh double_cone(test::Rng& rng, int rim, bool shuffle_rim) {
  Mesh mesh;
  mesh.points = {{0, 0, 1}, {0, 0, -1}};
  std::vector<VertexIndex> at(static_cast<std::size_t>(rim));
  for (int i = 0; i < rim; ++i) {
    at[static_cast<std::size_t>(i)] = static_cast<VertexIndex>(2 + i);
    const double u = 2 * std::numbers::pi * i / rim;
    mesh.points.push_back({std::cos(u), std::sin(u), 0});
  }
  if (shuffle_rim) {
    for (std::size_t i = at.size(); i > 1; --i) std::swap(at[i - 1], at[rng.engine() % i]);
    std::vector<Point3> points = mesh.points;
    for (int i = 0; i < rim; ++i)
      points[at[static_cast<std::size_t>(i)]] = mesh.points[static_cast<std::size_t>(2 + i)];
    mesh.points = points;
  }
  for (int i = 0; i < rim; ++i) {
    const VertexIndex a = at[static_cast<std::size_t>(i)], b = at[static_cast<std::size_t>((i + 1) % rim)];
    mesh.faces.push_back({{0, a, b}});
    mesh.faces.push_back({{1, b, a}});
  }
  for (std::size_t i = mesh.faces.size(); i > 1; --i)
    std::swap(mesh.faces[i - 1], mesh.faces[rng.engine() % i]);
  return mesh;
}

TEST(EdgeNumbering, FansOfThousandsRoundOneVertexNumberEdgesInFirstSeenOrder) {
  for (unsigned seed = 31; seed <= 34; ++seed) {
    test::Rng rng(seed);
    const Mesh mesh = double_cone(rng, seed % 2 == 0 ? 3000 : 700, seed > 32);
    const SolidBuildResult result = build(mesh);
    ASSERT_TRUE(result.ok()) << "seed " << seed;
    EXPECT_TRUE(result.solid->closed);
    expect_edges_as_named(mesh, *result.solid);
  }
}

// Meshes of 8 192 faces or more have their edges entered by two halves of the faces side by side, the
// second half's then taken into the first's table (edge_table.cpp, enter_plain_faces): the same contract.
TEST(EdgeNumbering, LargeMeshesEnteredByHalvesNumberEdgesInFirstSeenOrder) {
  for (unsigned seed = 41; seed <= 44; ++seed) {
    test::Rng rng(seed);
    const bool quads = seed % 2 == 0;
    Mesh mesh = shuffled_torus(rng, quads ? 180 : 130, quads ? 60 : 40, quads);
    if (seed > 42) {  // open: every fifth face left out
      Mesh open{mesh.points, {}};
      for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        if (f % 5 != 0) open.faces.push_back(mesh.faces[f]);
      mesh = open;
    }
    ASSERT_GE(mesh.faces.size(), 8192u);
    const SolidBuildResult result = build(mesh);
    ASSERT_TRUE(result.ok()) << "seed " << seed;
    EXPECT_EQ(result.solid->closed, seed <= 42);
    expect_edges_as_named(mesh, *result.solid);
  }
  test::Rng rng(45);
  expect_built_as_named(double_cone(rng, 5000, true));  // one hub's fan in each half's table
}

// An edge of three faces in a large mesh, its first use in the first half and the fin's in the second,
// and another whose three uses all lie in the second half: each reported with its faces in order, as
// face after face; and a vertex at another's position reported before them, in the vertex stage's place.
TEST(EdgeNumbering, LargeMeshesReportEdgesOfThreeFacesAndTwinVerticesInOrder) {
  test::Rng rng(46);
  Mesh mesh = shuffled_torus(rng, 120, 40, false);
  const std::size_t n = mesh.faces.size();
  mesh.points.push_back({9, 9, 9});
  const auto fin = static_cast<VertexIndex>(mesh.points.size() - 1);
  mesh.points.push_back(mesh.points[5]);  // a twin of vertex 5, on no face
  const std::size_t late = n - 10;
  for (const std::size_t f : {std::size_t{0}, late}) {
    const VertexIndex a = mesh.faces[f][0][0], b = mesh.faces[f][0][1];
    mesh.faces.push_back({{a, b, fin}});
  }
  const SolidBuildResult result = build(mesh);
  ASSERT_FALSE(result.ok());
  std::vector<std::string> codes, fins;
  for (const SolidDiagnostic& d : result.diagnostics) {
    codes.push_back(d.code);
    if (d.code == "non-manifold-edge") fins.push_back(d.message);
  }
  ASSERT_EQ(fins.size(), 2u);
  EXPECT_EQ(codes.front(), "duplicate-vertex");
  EXPECT_NE(fins[0].find("(1, "), std::string::npos) << fins[0];
  EXPECT_NE(fins[0].find(", " + std::to_string(n + 1) + ")"), std::string::npos) << fins[0];
  EXPECT_NE(fins[1].find(", " + std::to_string(late + 1) + ", " + std::to_string(n + 2) + ")"),
            std::string::npos)
      << fins[1];
}

}  // namespace
}  // namespace hlr
