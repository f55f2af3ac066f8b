// SolidBuilder's indexed input (add_vertex(Point3), add_indexed_face, add_indexed_line): the same solid
// and the same diagnostics as named input with the decimal ids, also when both styles are mixed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/core/solid/solid_test_helpers.hpp"

namespace hlr {
namespace {

using namespace solid_test;
using Rings = std::vector<std::vector<VertexIndex>>;

const Point3 kCube[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
// Counter-clockwise from outside, except face 3 (clockwise: reoriented with a warning).
const Rings kCubeFaces[6] = {{{0, 3, 2, 1}}, {{4, 5, 6, 7}}, {{0, 1, 5, 4}},
                             {{2, 6, 7, 3}}, {{0, 4, 7, 3}}, {{1, 2, 6, 5}}};

std::vector<std::string> named(const std::vector<VertexIndex>& ring) {
  std::vector<std::string> ids;
  for (VertexIndex v : ring) ids.push_back(std::to_string(v));
  return ids;
}

void expect_same(const SolidBuildResult& a, const SolidBuildResult& b) {
  ASSERT_EQ(a.diagnostics.size(), b.diagnostics.size()) << all_messages(a) << "vs\n" << all_messages(b);
  for (std::size_t i = 0; i < a.diagnostics.size(); ++i) {
    EXPECT_EQ(a.diagnostics[i].severity, b.diagnostics[i].severity);
    EXPECT_EQ(a.diagnostics[i].code, b.diagnostics[i].code);
    EXPECT_EQ(a.diagnostics[i].message, b.diagnostics[i].message);
    EXPECT_EQ(a.diagnostics[i].tag, b.diagnostics[i].tag);
  }
  ASSERT_EQ(a.ok(), b.ok());
  if (!a.ok()) return;
  const Solid &s = *a.solid, &t = *b.solid;
  EXPECT_EQ(s.vertices, t.vertices);
  ASSERT_EQ(s.faces.size(), t.faces.size());
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    ASSERT_EQ(s.faces[f].rings.size(), t.faces[f].rings.size());
    for (std::size_t k = 0; k < s.faces[f].rings.size(); ++k) {
      EXPECT_EQ(s.faces[f].rings[k].vertices, t.faces[f].rings[k].vertices);
      EXPECT_EQ(s.faces[f].rings[k].edges, t.faces[f].rings[k].edges);
    }
  }
  ASSERT_EQ(s.edges.size(), t.edges.size());
  for (std::size_t e = 0; e < s.edges.size(); ++e) {
    EXPECT_EQ(s.edges[e].v0, t.edges[e].v0);
    EXPECT_EQ(s.edges[e].v1, t.edges[e].v1);
    EXPECT_EQ(s.edges[e].left, t.edges[e].left);
    EXPECT_EQ(s.edges[e].right, t.edges[e].right);
    EXPECT_EQ(s.edges[e].kind, t.edges[e].kind);
  }
  EXPECT_EQ(s.closed, t.closed);
}

TEST(SolidIndexedBuilder, CubeMatchesNamedInput) {
  SolidBuilder indexed, by_name;
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(indexed.add_vertex(kCube[i], 10 + i), static_cast<VertexIndex>(i));
    by_name.add_vertex(std::to_string(i), kCube[i], 10 + i);
  }
  for (int f = 0; f < 6; ++f) {
    indexed.add_indexed_face(kCubeFaces[f], 20 + f);
    by_name.add_face(named(kCubeFaces[f][0]), {}, 20 + f);
  }
  indexed.add_indexed_line(0, 6, 30);  // through the cube: a free line
  by_name.add_line("0", "6", 30);
  const SolidBuildResult r = indexed.build();
  ASSERT_TRUE(r.ok()) << all_messages(r);
  expect_valid_solid(*r.solid);
  ASSERT_EQ(with_code(r, "reoriented").size(), 1u);
  EXPECT_EQ(with_code(r, "reoriented")[0]->tag, 23);
  EXPECT_EQ(count_kind(*r.solid, EdgeKind::Free), 1u);
  expect_same(r, by_name.build());
}

TEST(SolidIndexedBuilder, DiagnosticsNameVerticesByNumber) {
  SolidBuilder b;
  for (int i = 0; i < 4; ++i) b.add_vertex(kCube[i]);
  b.add_vertex(kCube[0]);  // vertex 4 coincides with vertex 0
  b.add_indexed_face(Rings{{0, 1, 9, 2, 9}}, 7);
  b.add_indexed_face(Rings{{0, 1, 1, 2, 3}});
  b.add_indexed_line(3, 3000000000u, 8);
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  const auto unknown = with_code(r, "unknown-vertex");
  ASSERT_EQ(unknown.size(), 2u) << all_messages(r);
  EXPECT_EQ(unknown[0]->message,
            "face 1 names vertex '9' which is not declared; declare it with 'vertex 9 = (x, y, z)' before "
            "the face");
  EXPECT_EQ(unknown[0]->tag, 7);
  EXPECT_EQ(
      unknown[1]->message,
      "line 1 names vertex '3000000000' which is not declared; declare it with 'vertex 3000000000 = (x, y, "
      "z)' before the line");
  ASSERT_EQ(with_code(r, "duplicate-vertex").size(), 1u);
  EXPECT_EQ(with_code(r, "duplicate-vertex")[0]->message, "vertex '4' is at the same position as vertex '0'");
  ASSERT_EQ(with_code(r, "repeated-vertex").size(), 1u);
  EXPECT_EQ(with_code(r, "repeated-vertex")[0]->message,
            "face 2 lists vertex '1' twice in a row; dropped the repeat");
  EXPECT_EQ(with_code(r, "repeated-vertex")[0]->tag, -1);  // untagged
}

TEST(SolidIndexedBuilder, MixedInputBehavesLikeDecimalIds) {
  // Indexed vertex 1 has id "1"; named faces and lines reach it by that id, and an indexed reference is
  // the decimal id: 0 names no vertex here, as vertex 0 is called "a".
  SolidBuilder b;
  b.add_vertex("a", {0, 0, 0});
  EXPECT_EQ(b.add_vertex(Point3{1, 0, 0}), 1u);
  b.add_vertex("2", {1, 1, 0});
  b.add_face({"a", "1", "2"}, {}, 5);
  b.add_indexed_face(Rings{{0, 1, 2}}, 6);
  const SolidBuildResult r = b.build();
  const auto unknown = with_code(r, "unknown-vertex");
  ASSERT_EQ(unknown.size(), 1u) << all_messages(r);
  EXPECT_EQ(unknown[0]->message,
            "face 2 names vertex '0' which is not declared; declare it with 'vertex 0 = (x, y, z)' before "
            "the face");
  EXPECT_EQ(unknown[0]->tag, 6);

  // An id declared by name and again by number is a duplicate like any other.
  SolidBuilder d;
  d.add_vertex("1", {0, 0, 0}, 3);
  d.add_vertex(Point3{5, 5, 5}, 4);  // number 1, id "1"
  const SolidBuildResult rd = d.build();
  ASSERT_EQ(with_code(rd, "duplicate-vertex").size(), 1u) << all_messages(rd);
  EXPECT_EQ(with_code(rd, "duplicate-vertex")[0]->message,
            "vertex '1' is declared twice; give each vertex its own id");
  EXPECT_EQ(with_code(rd, "duplicate-vertex")[0]->tag, 4);
}

TEST(SolidIndexedBuilder, PlateWithHoleAndLoopFaceMatchNamedInput) {
  // A square plate with a square hole as indexed rings, and the same face as one bridged loop.
  const Point3 p[8] = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0},
                       {1, 1, 0}, {1, 3, 0}, {3, 3, 0}, {3, 1, 0}};
  const Rings plate = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  SolidBuilder indexed, by_name;
  for (int i = 0; i < 8; ++i) {
    indexed.add_vertex(p[i]);
    by_name.add_vertex(std::to_string(i), p[i]);
  }
  indexed.add_indexed_face(plate, 1);
  by_name.add_face(named(plate[0]), {named(plate[1])}, 1);
  indexed.add_face_loop({"0", "1", "2", "3", "0", "4", "5", "6", "7", "4"}, 2);
  by_name.add_face_loop({"0", "1", "2", "3", "0", "4", "5", "6", "7", "4"}, 2);
  indexed.add_indexed_line(0, 2, 3);  // a diagonal crossing the hole: still a marking (end points only)
  by_name.add_line("0", "2", 3);
  const SolidBuildResult r = indexed.build();
  EXPECT_EQ(with_code(r, "reoriented").size(), 1u) << all_messages(r);  // two faces back to back
  expect_same(r, by_name.build());
}

// Faces added at once (add_indexed_polygons) build what the same faces added one by one build, tags and
// messages included: here after a face with a tag and one without, with face 3 wound the wrong way and
// a face naming vertex 8, which does not exist.
TEST(SolidIndexedBuilder, PolygonsAtOnceMatchOneByOne) {
  for (const std::int64_t first_tag : {std::int64_t{-1}, std::int64_t{100}}) {
    SolidBuilder at_once, one_by_one;
    for (SolidBuilder* b : {&at_once, &one_by_one})
      for (const Point3& p : kCube) b->add_vertex(p);
    for (SolidBuilder* b : {&at_once, &one_by_one}) {
      b->add_indexed_polygon(kCubeFaces[0][0], 7);
      b->add_indexed_polygon(kCubeFaces[1][0]);
    }
    std::vector<VertexIndex> vertices;
    std::vector<std::size_t> ends;
    for (int f = 2; f < 6; ++f) {
      const std::vector<VertexIndex>& ring = kCubeFaces[f][0];
      vertices.insert(vertices.end(), ring.begin(), ring.end());
      ends.push_back(vertices.size());
      one_by_one.add_indexed_polygon(ring, first_tag == -1 ? -1 : first_tag + f - 2);
    }
    vertices.insert(vertices.end(), {0, 1, 8});
    ends.push_back(vertices.size());
    one_by_one.add_indexed_polygon(std::vector<VertexIndex>{0, 1, 8}, first_tag == -1 ? -1 : first_tag + 4);
    at_once.add_indexed_polygons(vertices, ends, first_tag);
    const SolidBuildResult a = at_once.build(), b = one_by_one.build();
    EXPECT_FALSE(a.ok());  // vertex 8
    EXPECT_GE(a.diagnostics.size(), 2u) << all_messages(a);
    expect_same(a, b);
  }
  SolidBuilder bad;
  const std::vector<VertexIndex> ring = {0, 1, 2};
  EXPECT_THROW(bad.add_indexed_polygons(ring, std::vector<std::size_t>{2, 1}), std::invalid_argument);
  EXPECT_THROW(bad.add_indexed_polygons(ring, std::vector<std::size_t>{4}), std::invalid_argument);
}

// A torus of 200 × 100 quads split into triangles: enough faces and vertices that add_vertices and
// add_indexed_polygons fill their lists by parts side by side.
struct TorusMesh {
  std::vector<Point3> points;
  std::vector<VertexIndex> vertices;
  std::vector<std::size_t> ends;
};
TorusMesh torus_mesh() {
  constexpr int nu = 200, nv = 100;
  TorusMesh t;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * std::numbers::pi * i / nu, v = 2 * std::numbers::pi * j / nv;
      t.points.push_back({(3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v)});
    }
  auto at = [](int i, int j) { return static_cast<VertexIndex>((i % nu) * nv + j % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      for (const VertexIndex v :
           {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)}) {
        t.vertices.push_back(v);
        if (t.vertices.size() % 3 == 0) t.ends.push_back(t.vertices.size());
      }
  return t;
}

// Many vertices and faces at once (add_vertices, add_indexed_polygons, by parts) build what the same
// added one by one build: a clean torus; the same with a vertex repeated at another's position (tagged
// errors) and two faces, one among the first and one among the last, naming a vertex number too large to
// be indexed.
TEST(SolidIndexedBuilder, ManyAtOnceMatchOneByOne) {
  const TorusMesh t = torus_mesh();
  ASSERT_EQ(t.ends.size(), 40000u);
  for (const bool broken : {false, true}) {
    std::vector<Point3> points = t.points;
    std::vector<VertexIndex> vertices = t.vertices;
    if (broken) {
      points.push_back(points[123]);
      vertices[4] = vertices[3 * 35'000 + 1] = solid_detail::kIndexRef + 5;
    }
    std::vector<std::int64_t> tags(points.size());
    for (std::size_t i = 0; i < tags.size(); ++i) tags[i] = 3 * static_cast<std::int64_t>(i) + 1;
    SolidBuilder at_once, one_by_one;
    EXPECT_EQ(at_once.add_vertices(points, tags), 0u);
    for (std::size_t i = 0; i < points.size(); ++i) one_by_one.add_vertex(points[i], tags[i]);
    at_once.add_indexed_polygons(vertices, t.ends, 7);
    for (std::size_t f = 0; f < t.ends.size(); ++f)
      one_by_one.add_indexed_polygon(std::span<const VertexIndex>(vertices).subspan(3 * f, 3),
                                     7 + static_cast<std::int64_t>(f));
    const SolidBuildResult a = at_once.build(), b = one_by_one.build();
    EXPECT_EQ(a.ok(), !broken) << all_messages(a);
    expect_same(a, b);
  }
}

// add_vertices keeps the tags of vertices added before and after it as one by one would, tagged or not.
TEST(SolidIndexedBuilder, VerticesAtOnceKeepTags) {
  const std::vector<Point3> corners(std::begin(kCube), std::end(kCube));
  const std::vector<std::int64_t> tags = {10, 11, 12, 13};
  SolidBuilder at_once, one_by_one;
  at_once.add_vertex(corners[0]);                                         // untagged
  EXPECT_EQ(at_once.add_vertices(std::span(corners).subspan(1, 3)), 1u);  // untagged
  EXPECT_EQ(at_once.add_vertices(std::span(corners).subspan(4, 4), tags), 4u);
  at_once.add_vertices(std::vector<Point3>{corners[2], corners[5]});  // untagged twins: errors
  for (std::size_t i = 0; i < 8; ++i) one_by_one.add_vertex(corners[i], i < 4 ? -1 : tags[i - 4]);
  one_by_one.add_vertex(corners[2]);
  one_by_one.add_vertex(corners[5]);
  for (SolidBuilder* b : {&at_once, &one_by_one})
    for (const Rings& face : kCubeFaces) b->add_indexed_face(face, 20);
  const SolidBuildResult a = at_once.build();
  EXPECT_EQ(with_code(a, "duplicate-vertex").size(), 2u) << all_messages(a);
  expect_same(a, one_by_one.build());
  EXPECT_THROW(at_once.add_vertices(corners, tags), std::invalid_argument);  // one tag a vertex, or none
}

}  // namespace
}  // namespace hlr
