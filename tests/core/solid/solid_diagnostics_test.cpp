// Every diagnostic SolidBuilder reports: code, severity, tag and the words of the message.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "tests/core/solid/solid_test_helpers.hpp"

namespace hlr {
namespace {

using namespace solid_test;
using Severity = SolidDiagnostic::Severity;

// The one diagnostic with `code`; fails the test if there is not exactly one.
const SolidDiagnostic& only(const SolidBuildResult& r, const std::string& code) {
  static const SolidDiagnostic none{};
  const auto found = with_code(r, code);
  EXPECT_EQ(found.size(), 1u) << all_messages(r);
  return found.empty() ? none : *found[0];
}

SolidBuilder square(SolidBuildOptions o = {}) {
  SolidBuilder b(o);
  b.add_vertex("a", {0, 0, 0}, 1);
  b.add_vertex("b", {1, 0, 0}, 2);
  b.add_vertex("c", {1, 1, 0}, 3);
  b.add_vertex("d", {0, 1, 0}, 4);
  return b;
}

TEST(SolidDiagnostics, UnknownVertexInFace) {
  SolidBuilder b = square();
  b.add_face({"a", "b", "q", "c", "q"}, {}, 77);
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  const SolidDiagnostic& d = only(r, "unknown-vertex");  // named once although used twice
  EXPECT_EQ(d.severity, Severity::Error);
  EXPECT_EQ(d.message, "face 1 names vertex 'q' which is not declared; declare it with 'vertex q = (x, y, z)' before the face");
  EXPECT_EQ(d.tag, 77);
}

TEST(SolidDiagnostics, UnknownVertexInLine) {
  SolidBuilder b = square();
  b.add_line("a", "b", 5);
  b.add_line("a", "zz", 6);
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  const SolidDiagnostic& d = only(r, "unknown-vertex");
  EXPECT_EQ(d.message, "line 2 names vertex 'zz' which is not declared; declare it with 'vertex zz = (x, y, z)' before the line");
  EXPECT_EQ(d.tag, 6);
}

TEST(SolidDiagnostics, TooFewVertices) {
  SolidBuilder b = square();
  b.add_face({"a", "b"}, {}, 10);
  b.add_face({"a", "b", "c", "d"}, {{"a", "b"}}, 11);
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  const auto found = with_code(r, "too-few-vertices");
  ASSERT_EQ(found.size(), 2u) << all_messages(r);
  EXPECT_EQ(found[0]->message, "face 1 has only 2 distinct vertices; a face needs at least 3");
  EXPECT_EQ(found[0]->tag, 10);
  EXPECT_EQ(found[1]->message, "hole 1 of face 2 has only 2 distinct vertices; a hole needs at least 3");
  EXPECT_EQ(found[1]->tag, 11);
}

TEST(SolidDiagnostics, RepeatedVertexInARowIsDroppedWithAWarning) {
  SolidBuilder b = square();
  b.add_face({"a", "b", "b", "c", "d", "a"}, {}, 12);
  const SolidBuildResult r = b.build();
  ASSERT_TRUE(r.ok()) << all_messages(r);
  const auto found = with_code(r, "repeated-vertex");
  ASSERT_EQ(found.size(), 2u) << all_messages(r);
  EXPECT_EQ(found[0]->severity, Severity::Warning);
  EXPECT_EQ(found[0]->message, "face 1 lists vertex 'b' twice in a row; dropped the repeat");
  EXPECT_EQ(found[1]->message, "face 1 lists vertex 'a' twice in a row; dropped the repeat");  // last = first
  EXPECT_EQ(found[0]->tag, 12);
  EXPECT_EQ(r.solid->faces[0].rings[0].vertices.size(), 4u);
  EXPECT_EQ(r.solid->edges.size(), 4u);
}

TEST(SolidDiagnostics, RepeatsLeavingTooFewVertices) {
  SolidBuilder b = square();
  b.add_face_loop({"a", "b", "b", "a"}, 13);
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(with_code(r, "repeated-vertex").size(), 2u) << all_messages(r);
  EXPECT_EQ(only(r, "too-few-vertices").message, "face 1 has only 2 distinct vertices; a face needs at least 3");
}

TEST(SolidDiagnostics, NonPlanarFaceReportsItsDeviation) {
  SolidBuilder b;
  const Point3 p[5] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 3, 0.25}, {0, 2, 0}};
  std::vector<std::string> ids;
  for (int i = 0; i < 5; ++i) {
    ids.push_back(id("p", i));
    b.add_vertex(ids.back(), p[i]);
  }
  b.add_face(ids, {}, 14);
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  // Expected deviation, computed here from the definition: distance to the plane through the vertex
  // mean with Newell's normal.
  std::vector<Point3> pts(p, p + 5);
  Ring ring{{0, 1, 2, 3, 4}};
  const Vector3 n = normalize(newell_normal(pts, ring));
  Vector3 mean{};
  for (const Point3& q : pts) mean += to_vector(q) / 5;
  double worst = 0;
  int worst_i = -1;
  for (int i = 0; i < 5; ++i) {
    const double dev = std::abs(dot(n, to_vector(p[i]) - mean));
    if (dev > worst) worst = dev, worst_i = i;
  }
  ASSERT_EQ(worst_i, 3);
  std::ostringstream value;
  value << worst;
  const SolidDiagnostic& d = only(r, "non-planar");
  EXPECT_EQ(d.severity, Severity::Error);
  EXPECT_EQ(d.message, "face 1 is not planar: vertex p3 lies " + value.str() +
                           " off the face's mean plane (tolerance 1e-06 × face size); split it into planar faces");
  EXPECT_EQ(d.tag, 14);
  EXPECT_GT(worst, 0.1);
}

TEST(SolidDiagnostics, LoosenedPlanarityAcceptsWithAWarning) {
  SolidBuildOptions o;
  o.planarity_tolerance = 1e-3;
  SolidBuilder b = square(o);
  b.add_vertex("e", {0.5, 1.5, 1e-4}, 5);
  b.add_face({"a", "b", "c", "e", "d"}, {}, 15);
  const SolidBuildResult r = b.build();
  ASSERT_TRUE(r.ok()) << all_messages(r);
  const SolidDiagnostic& d = only(r, "non-planar");
  EXPECT_EQ(d.severity, Severity::Warning);
  EXPECT_NE(d.message.find("face 1 is not planar: vertex e lies "), std::string::npos) << d.message;
  EXPECT_NE(d.message.find("accepted by the planarity tolerance 0.001"), std::string::npos) << d.message;
}

TEST(SolidDiagnostics, ZeroArea) {
  SolidBuilder b = square();
  b.add_vertex("m", {0.5, 0, 0});
  for (int i = 1; i <= 3; ++i) b.add_vertex(id("h", i), {0.2 * i, 0.2 * i, 0});
  b.add_face({"a", "m", "b"}, {}, 16);                          // collinear
  b.add_face_loop({"a", "b", "c", "b"}, 17);                   // every edge doubled
  b.add_face({"a", "b", "c", "d"}, {{"h1", "h2", "h3"}}, 18);  // flat hole
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  const auto found = with_code(r, "zero-area");
  ASSERT_EQ(found.size(), 3u) << all_messages(r);
  EXPECT_EQ(found[0]->message, "face 1 has zero area");
  EXPECT_EQ(found[0]->tag, 16);
  EXPECT_EQ(found[1]->message, "face 2 has zero area: every edge of its loop is traversed in both directions");
  EXPECT_EQ(found[2]->message, "hole 1 of face 3 has zero area");
}

TEST(SolidDiagnostics, DuplicateVertexIdAndPosition) {
  SolidBuilder b = square();
  b.add_vertex("a", {5, 5, 5}, 20);
  b.add_vertex("b2", {1, 0, 0}, 21);
  b.add_vertex("b3", {1, 0, 1e-12}, 22);  // within the scene tolerance of b
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  const auto found = with_code(r, "duplicate-vertex");
  ASSERT_EQ(found.size(), 3u) << all_messages(r);
  EXPECT_EQ(found[0]->message, "vertex 'a' is declared twice; give each vertex its own id");
  EXPECT_EQ(found[0]->tag, 20);
  EXPECT_EQ(found[1]->message, "vertex 'b2' is at the same position as vertex 'b'");
  EXPECT_EQ(found[1]->tag, 21);
  EXPECT_EQ(found[2]->message, "vertex 'b3' is at the same position as vertex 'b'");
  EXPECT_EQ(found[2]->tag, 22);
}

TEST(SolidDiagnostics, NonFiniteCoordinates) {
  SolidBuilder b = square();
  b.add_vertex("x", {0, std::nan(""), 0}, 30);
  b.add_vertex("y", {0, 0, -std::numeric_limits<double>::infinity()}, 31);
  b.add_face({"a", "b", "x"}, {}, 32);  // uses a bad vertex: no second report
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  const auto found = with_code(r, "non-finite");
  ASSERT_EQ(found.size(), 2u) << all_messages(r);
  EXPECT_EQ(found[0]->message, "vertex 'x' has a non-finite coordinate (nan)");
  EXPECT_EQ(found[0]->tag, 30);
  EXPECT_EQ(found[1]->message, "vertex 'y' has a non-finite coordinate (-inf)");
  EXPECT_EQ(r.diagnostics.size(), 2u) << all_messages(r);
}

TEST(SolidDiagnostics, EdgeUsedByThreeFaces) {
  SolidBuilder b;
  b.add_vertex("3", {0, 0, 0});
  b.add_vertex("4", {1, 0, 0});
  b.add_vertex("p", {0, 1, 0});
  b.add_vertex("q", {0, 0, 1});
  b.add_vertex("r", {0, -1, 0});
  b.add_face({"3", "4", "p"}, {}, 40);
  b.add_face({"4", "3", "q"}, {}, 41);
  b.add_face({"3", "4", "r"}, {}, 42);
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  const SolidDiagnostic& d = only(r, "non-manifold-edge");
  EXPECT_EQ(d.message, "edge 3\u20134 is used by 3 faces (1, 2, 3); an edge may border at most two faces");
  EXPECT_EQ(d.tag, 42);
}

TEST(SolidDiagnostics, EdgeTraversedTwiceByOneFace) {
  SolidBuilder b = square();
  b.add_face_loop({"a", "b", "c", "a", "b", "c"}, 43);
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  const SolidDiagnostic& d = only(r, "non-manifold-edge");
  EXPECT_EQ(d.message,
            "face 1 runs along edge a\u2013b twice in the same direction; each edge may appear once in a face's "
            "boundary");
  EXPECT_EQ(d.tag, 43);
}

TEST(SolidDiagnostics, MoebiusBandCannotBeOriented) {
  // Five triangles (i, i+1, i+2 mod 5): the minimal Möbius band.
  SolidBuilder b;
  for (int i = 0; i < 5; ++i) {
    const double t = 2 * 3.14159265358979 * i / 5;
    b.add_vertex(std::to_string(i), {std::cos(t), std::sin(t), i % 2 ? 0.5 : -0.5});
  }
  for (int i = 0; i < 5; ++i)
    b.add_face({std::to_string(i), std::to_string((i + 1) % 5), std::to_string((i + 2) % 5)}, {}, 50 + i);
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  const SolidDiagnostic& d = only(r, "non-orientable");
  EXPECT_EQ(d.severity, Severity::Error);
  EXPECT_NE(d.message.find("cannot be wound consistently around edge"), std::string::npos) << d.message;
  EXPECT_NE(d.message.find("one-sided"), std::string::npos) << d.message;
  EXPECT_EQ(d.message.rfind("faces ", 0), 0u) << d.message;
}

TEST(SolidDiagnostics, BadHoles) {
  SolidBuilder b;
  const double outer[4][2] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  for (int i = 0; i < 4; ++i) b.add_vertex(id("o", i), {outer[i][0], outer[i][1], 0});
  auto square_at = [&](const std::string& name, double x, double y, double size) {
    std::vector<std::string> ids;
    const double c[4][2] = {{x, y}, {x + size, y}, {x + size, y + size}, {x, y + size}};
    for (int i = 0; i < 4; ++i) {
      ids.push_back(id(name, i));
      b.add_vertex(ids.back(), {c[i][0], c[i][1], 0});
    }
    return ids;
  };
  const auto outside = square_at("u", 8, 8, 4), h1 = square_at("h", 1, 1, 3), h2 = square_at("k", 2, 2, 3);
  const std::vector<std::string> o = {"o0", "o1", "o2", "o3"};
  b.add_face(o, {outside}, 60);
  b.add_face(o, {h1, h2}, 61);
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  const auto found = with_code(r, "bad-hole");
  ASSERT_EQ(found.size(), 2u) << all_messages(r);
  EXPECT_EQ(found[0]->message,
            "hole 1 of face 1 is not inside the face: vertex 'u1' lies outside its outer boundary; a hole must lie "
            "within the outer ring");
  EXPECT_EQ(found[0]->tag, 60);
  EXPECT_NE(found[1]->message.find("hole 2 of face 2 crosses hole 1 of face 2 (edges "), std::string::npos)
      << found[1]->message;
  EXPECT_NE(found[1]->message.find("holes must lie inside the face without crossing"), std::string::npos);
  EXPECT_EQ(found[1]->tag, 61);
}

TEST(SolidDiagnostics, DegenerateLine) {
  SolidBuilder b = square();
  b.add_line("c", "c", 70);
  const SolidBuildResult r = b.build();
  ASSERT_TRUE(r.ok());
  const SolidDiagnostic& d = only(r, "degenerate-line");
  EXPECT_EQ(d.severity, Severity::Warning);
  EXPECT_EQ(d.message, "line 1 joins vertex 'c' to itself; dropped it");
  EXPECT_EQ(d.tag, 70);
  EXPECT_TRUE(r.solid->edges.empty());
}

TEST(SolidDiagnostics, AllProblemsAreCollected) {
  SolidBuilder b = square();
  b.add_vertex("n", {std::nan(""), 0, 0});
  b.add_vertex("a", {9, 9, 9});
  b.add_vertex("lift", {0.5, 0.5, 3});
  b.add_face({"a", "b", "zz"});
  b.add_face({"a", "b"});
  b.add_face({"a", "b", "c", "lift", "d"});
  b.add_face({"a", "b", "n"});
  b.add_line("a", "nothing");
  const SolidBuildResult r = b.build();
  EXPECT_FALSE(r.ok());
  for (const char* code : {"non-finite", "duplicate-vertex", "unknown-vertex", "too-few-vertices", "non-planar"})
    EXPECT_FALSE(with_code(r, code).empty()) << code << "\n" << all_messages(r);
  EXPECT_EQ(with_code(r, "unknown-vertex").size(), 2u);
}

}  // namespace
}  // namespace hlr
