// SolidBuilder on small solids: orientation, edge kinds, holes, markings and robustness.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>
#include <random>

#include "tests/core/solid/solid_test_helpers.hpp"

namespace hlr {
namespace {

using namespace solid_test;

TEST(SolidBuilder, UnitCube) {
  const SolidBuildResult r = unit_cube().build();
  ASSERT_TRUE(r.ok()) << all_messages(r);
  EXPECT_TRUE(r.diagnostics.empty()) << all_messages(r);
  const Solid& s = *r.solid;
  expect_valid_solid(s);
  EXPECT_EQ(s.vertices.size(), 8u);
  EXPECT_EQ(s.faces.size(), 6u);
  EXPECT_EQ(s.edges.size(), 12u);
  EXPECT_EQ(count_kind(s, EdgeKind::Feature), 12u);
  EXPECT_EQ(count_concave(s), 0u);
  EXPECT_TRUE(s.closed);
  EXPECT_NEAR(signed_volume(s), 1, 1e-12);
  // Vertices keep insertion order; planes are outward with the right offset.
  EXPECT_EQ(s.vertices[6], Point3(1, 1, 1));
  EXPECT_NEAR(s.planes[1].normal.z, 1, 1e-15);  // top
  EXPECT_NEAR(s.planes[1].offset, -1, 1e-15);
  EXPECT_NEAR(s.planes[2].normal.y, -1, 1e-15);  // front
  // Edge 1–2 (indices 0, 1): bottom runs 2→1, front runs 1→2, so left = front.
  const SolidEdge* e = find_edge(s, 0, 1);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->v0, 0u);
  EXPECT_EQ(e->left, 2);
  EXPECT_EQ(e->right, 0);
}

TEST(SolidBuilder, CubeWithOneFaceClockwiseIsReoriented) {
  const SolidBuildResult r = unit_cube({3}).build();
  ASSERT_TRUE(r.ok()) << all_messages(r);
  const auto warnings = with_code(r, "reoriented");
  ASSERT_EQ(warnings.size(), 1u) << all_messages(r);
  EXPECT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(warnings[0]->severity, SolidDiagnostic::Severity::Warning);
  EXPECT_EQ(warnings[0]->message, "face 4 was wound clockwise seen from outside, unlike its neighbours; reversed it");
  EXPECT_EQ(warnings[0]->tag, 203);
  expect_valid_solid(*r.solid);
  EXPECT_TRUE(r.solid->closed);
  EXPECT_NEAR(signed_volume(*r.solid), 1, 1e-12);
  EXPECT_NEAR(r.solid->planes[3].normal.y, 1, 1e-15);  // back face points out again
}

TEST(SolidBuilder, InsideOutCubeIsTurnedOutwardWithAWarningPerFace) {
  const SolidBuildResult r = unit_cube({0, 1, 2, 3, 4, 5}).build();
  ASSERT_TRUE(r.ok()) << all_messages(r);
  const auto warnings = with_code(r, "reoriented");
  ASSERT_EQ(warnings.size(), 6u) << all_messages(r);
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(warnings[static_cast<std::size_t>(f)]->message,
              id("face ", f + 1) +
                  " was wound clockwise seen from outside, like every face of its solid (the solid was inside out); "
                  "reversed it");
    EXPECT_EQ(warnings[static_cast<std::size_t>(f)]->tag, 200 + f);
  }
  expect_valid_solid(*r.solid);
  EXPECT_NEAR(signed_volume(*r.solid), 1, 1e-12);
}

TEST(SolidBuilder, MixedWindingFollowsVolumeNotMajority) {
  // Four of six faces clockwise: the majority is wrong, the volume decides.
  const SolidBuildResult r = unit_cube({0, 1, 2, 3}).build();
  ASSERT_TRUE(r.ok()) << all_messages(r);
  EXPECT_EQ(with_code(r, "reoriented").size(), 4u);
  EXPECT_NEAR(signed_volume(*r.solid), 1, 1e-12);
}

TEST(SolidBuilder, WindingErrorWhenFixingIsOff) {
  SolidBuildOptions o;
  o.fix_winding = false;
  const SolidBuildResult r = unit_cube({5}, o).build();
  EXPECT_FALSE(r.ok());
  const auto errors = with_code(r, "reoriented");
  ASSERT_EQ(errors.size(), 1u) << all_messages(r);
  EXPECT_EQ(errors[0]->severity, SolidDiagnostic::Severity::Error);
  EXPECT_EQ(errors[0]->message,
            "face 6 is wound clockwise seen from outside, unlike its neighbours; list its vertices in the opposite order");
  EXPECT_EQ(errors[0]->tag, 205);
}

TEST(SolidBuilder, OpenQuadHasFourBoundaryEdges) {
  for (bool reversed : {false, true}) {
    SolidBuilder b;
    b.add_vertex("a", {0, 0, 0});
    b.add_vertex("b", {2, 0, 0});
    b.add_vertex("c", {2, 1, 0});
    b.add_vertex("d", {0, 1, 0});
    b.add_face(reversed ? std::vector<std::string>{"d", "c", "b", "a"} : std::vector<std::string>{"a", "b", "c", "d"});
    const SolidBuildResult r = b.build();
    ASSERT_TRUE(r.ok()) << all_messages(r);
    EXPECT_TRUE(r.diagnostics.empty()) << all_messages(r);  // nothing to be inconsistent with
    const Solid& s = *r.solid;
    expect_valid_solid(s);
    EXPECT_FALSE(s.closed);
    ASSERT_EQ(s.edges.size(), 4u);
    EXPECT_EQ(count_kind(s, EdgeKind::Boundary), 4u);
    for (const SolidEdge& e : s.edges) {
      EXPECT_EQ(e.left, 0);
      EXPECT_EQ(e.right, kNoFace);
      EXPECT_FALSE(e.concave);
    }
    EXPECT_NEAR(s.planes[0].normal.z, reversed ? -1 : 1, 1e-15);
  }
}

TEST(SolidBuilder, TessellatedQuadDiagonalIsFlat) {
  SolidBuilder b;
  b.add_vertex("1", {0, 0, 0});
  b.add_vertex("2", {1, 0, 0});
  b.add_vertex("3", {1, 1, 0});
  b.add_vertex("4", {0, 1, 0});
  b.add_face({"1", "2", "3"});
  b.add_face({"1", "3", "4"});
  const SolidBuildResult r = b.build();
  ASSERT_TRUE(r.ok()) << all_messages(r);
  const Solid& s = *r.solid;
  expect_valid_solid(s);
  ASSERT_EQ(s.edges.size(), 5u);
  const SolidEdge* diagonal = find_edge(s, 0, 2);
  ASSERT_NE(diagonal, nullptr);
  EXPECT_EQ(diagonal->kind, EdgeKind::Flat);
  EXPECT_FALSE(diagonal->concave);
  EXPECT_EQ(diagonal->left, 1);  // face 2 runs 1→3
  EXPECT_EQ(diagonal->right, 0);
  EXPECT_EQ(count_kind(s, EdgeKind::Boundary), 4u);
  EXPECT_FALSE(s.closed);
}

// A prism over a regular polygon with `sides` sides (a coarse cylinder of radius 1, height 2).
SolidBuilder cylinder(int sides, double crease) {
  SolidBuildOptions o;
  o.crease_angle_deg = crease;
  SolidBuilder b(o);
  std::vector<std::string> bottom, top;
  for (int i = 0; i < sides; ++i) {
    const double a = 2 * std::numbers::pi * i / sides;
    b.add_vertex(id("b", i), {std::cos(a), std::sin(a), 0});
    b.add_vertex(id("t", i), {std::cos(a), std::sin(a), 2});
    bottom.insert(bottom.begin(), id("b", i));
    top.push_back(id("t", i));
  }
  b.add_face(bottom);
  b.add_face(top);
  for (int i = 0; i < sides; ++i) {
    const int j = (i + 1) % sides;
    b.add_face({id("b", i), id("b", j), id("t", j), id("t", i)});
  }
  return b;
}

TEST(SolidBuilder, CreaseAngleMakesCylinderSidesSmooth) {
  const int sides = 16;  // 22.5° between neighbouring side faces
  for (double crease : {0.0, 30.0}) {
    const SolidBuildResult r = cylinder(sides, crease).build();
    ASSERT_TRUE(r.ok()) << all_messages(r);
    const Solid& s = *r.solid;
    expect_valid_solid(s);
    EXPECT_TRUE(s.closed);
    EXPECT_EQ(s.crease_angle_deg, crease);
    EXPECT_EQ(s.edges.size(), 3u * sides);
    EXPECT_EQ(count_concave(s), 0u);
    std::size_t vertical_smooth = 0, vertical = 0;
    for (const SolidEdge& e : s.edges) {
      const bool is_vertical = s.vertices[e.v0].z != s.vertices[e.v1].z;
      if (!is_vertical) {
        EXPECT_EQ(e.kind, EdgeKind::Feature);  // caps meet the sides at 90°
        continue;
      }
      ++vertical;
      if (e.kind == EdgeKind::Smooth) ++vertical_smooth;
    }
    EXPECT_EQ(vertical, static_cast<std::size_t>(sides));
    EXPECT_EQ(vertical_smooth, crease > 0 ? static_cast<std::size_t>(sides) : 0u);
  }
  // Just below the dihedral: Feature again.
  const SolidBuildResult r = cylinder(sides, 22.0).build();
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(count_kind(*r.solid, EdgeKind::Smooth), 0u);
}

// A 4×4 plate, 1 thick, with a 2×2 square hole through it. Corners: outer o0..o3, hole h0..h3, at z = 0
// ("b" prefix) and z = 1 ("t" prefix).
SolidBuilder plate_with_hole(bool top_as_loop, std::uint32_t reversed_faces = 0) {
  SolidBuilder b;
  // Faces whose bit is set in `reversed_faces` are listed in the opposite order.
  int next_face = 0;
  auto face = [&](std::vector<std::string> outer, std::vector<std::vector<std::string>> holes, std::int64_t tag) {
    if (reversed_faces >> next_face++ & 1) {
      std::reverse(outer.begin(), outer.end());
      for (auto& h : holes) std::reverse(h.begin(), h.end());
    }
    b.add_face(outer, holes, tag);
  };
  const double outer[4][2] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}}, hole[4][2] = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
  for (const char* level : {"b", "t"}) {
    const double z = level[0] == 't' ? 1 : 0;
    for (int i = 0; i < 4; ++i) b.add_vertex(std::string(level) + id("o", i), {outer[i][0], outer[i][1], z});
    for (int i = 0; i < 4; ++i) b.add_vertex(std::string(level) + id("h", i), {hole[i][0], hole[i][1], z});
  }
  if (top_as_loop)  // Desens' style: one loop, the hole reached by the doubled bridge to0–th0
    b.add_face_loop({"to0", "to1", "to2", "to3", "to0", "th0", "th3", "th2", "th1", "th0"}, 1);
  else  // hole listed counter-clockwise on purpose: the builder orients holes itself
    face({"to0", "to1", "to2", "to3"}, {{"th0", "th1", "th2", "th3"}}, 1);
  if (top_as_loop) ++next_face;
  face({"bo0", "bo3", "bo2", "bo1"}, {{"bh0", "bh3", "bh2", "bh1"}}, 2);
  for (int i = 0; i < 4; ++i) {
    const std::string a = std::to_string(i), c = std::to_string((i + 1) % 4);
    face({"bo" + a, "bo" + c, "to" + c, "to" + a}, {}, 3 + 2 * i);  // outer walls face out
    face({"bh" + c, "bh" + a, "th" + a, "th" + c}, {}, 4 + 2 * i);  // hole walls face the hole's axis
  }
  return b;
}

TEST(SolidBuilder, PlateWithHoleIsAClosedTorus) {
  for (bool loop : {false, true}) {
    const SolidBuildResult r = plate_with_hole(loop).build();
    ASSERT_TRUE(r.ok()) << all_messages(r);
    EXPECT_TRUE(r.diagnostics.empty()) << all_messages(r);
    const Solid& s = *r.solid;
    expect_valid_solid(s);  // includes: holes clockwise seen from outside
    EXPECT_TRUE(s.closed);
    ASSERT_EQ(s.faces.size(), 10u);
    EXPECT_EQ(s.faces[0].rings.size(), 2u);
    EXPECT_EQ(s.faces[1].rings.size(), 2u);
    EXPECT_NEAR(signed_volume(s), 16 - 4, 1e-12);
    // Euler–Poincaré for faces with holes: V − E + F − H = 2(S − G) with one shell of genus 1.
    std::size_t ring_edges = 0, holes = 0;
    for (const SolidEdge& e : s.edges) ring_edges += e.kind != EdgeKind::Marking && e.kind != EdgeKind::Free;
    for (const Face& f : s.faces) holes += f.rings.size() - 1;
    EXPECT_EQ(static_cast<long>(s.vertices.size()) - static_cast<long>(ring_edges) +
                  static_cast<long>(s.faces.size()) - static_cast<long>(holes),
              0);
    EXPECT_EQ(ring_edges, 24u);
    EXPECT_EQ(count_concave(s), 4u);  // the hole's vertical corners
    for (const SolidEdge& e : s.edges) {
      if (e.concave) {
        EXPECT_NE(s.vertices[e.v0].z, s.vertices[e.v1].z);
      }
    }
    // The bridge of the loop form is a marking on the top face; otherwise there is none.
    EXPECT_EQ(count_kind(s, EdgeKind::Marking), loop ? 1u : 0u);
    if (loop) {
      const SolidEdge* bridge = find_edge(s, 8, 12);  // to0 = index 8, th0 = index 12
      ASSERT_NE(bridge, nullptr);
      EXPECT_EQ(bridge->kind, EdgeKind::Marking);
      EXPECT_EQ(bridge->left, 0);
      EXPECT_EQ(bridge->right, 0);
    }
  }
}

// Any set of reversed faces of a non-convex solid of genus 1 is put right, with one warning per
// reversed face, and the result encloses the right volume.
TEST(SolidBuilder, RandomlyReversedFacesOfAPlateAreReoriented) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 60; ++trial) {
    const std::uint32_t reversed = rng() & 0x3ff;
    SCOPED_TRACE(id("reversed faces mask ", reversed));
    const SolidBuildResult r = plate_with_hole(false, reversed).build();
    ASSERT_TRUE(r.ok()) << all_messages(r);
    const auto warnings = with_code(r, "reoriented");
    EXPECT_EQ(warnings.size(), static_cast<std::size_t>(std::popcount(reversed))) << all_messages(r);
    for (const SolidDiagnostic* d : warnings) EXPECT_TRUE(reversed >> (d->tag - 1) & 1) << d->message;
    expect_valid_solid(*r.solid);
    EXPECT_NEAR(signed_volume(*r.solid), 12, 1e-12);
  }
}

TEST(SolidBuilder, HoleTouchingTheOuterRingAtAVertex) {
  // A loop whose inner ring shares one vertex with the outer (Desens' face 17): no bridge to cancel.
  SolidBuilder b;
  b.add_vertex("p", {0, 0, 0});
  b.add_vertex("a", {4, -2, 0});
  b.add_vertex("b", {4, 2, 0});
  b.add_vertex("q", {2, -0.5, 0});
  b.add_vertex("r", {2, 0.5, 0});
  b.add_face_loop({"p", "r", "q", "p", "a", "b"});
  const SolidBuildResult r = b.build();
  ASSERT_TRUE(r.ok()) << all_messages(r);
  const Solid& s = *r.solid;
  ASSERT_EQ(s.faces[0].rings.size(), 2u);
  EXPECT_EQ(s.faces[0].rings[0].vertices, (std::vector<VertexIndex>{0, 1, 2}));
  EXPECT_EQ(s.faces[0].rings[1].vertices.size(), 3u);
  expect_valid_solid(s);
  EXPECT_EQ(count_kind(s, EdgeKind::Boundary), 6u);
}

TEST(SolidBuilder, LinesBecomeMarkingsOrFreeLines) {
  SolidBuilder b = unit_cube();
  b.add_vertex("m1", {0.25, 0.5, 1});  // on the top face
  b.add_vertex("m2", {0.75, 0.5, 1});
  b.add_vertex("far", {3, 3, 1});       // in the top face's plane, outside it
  b.add_vertex("edge", {0.5, 0, 1});    // on the top face's boundary
  b.add_line("5", "7", 301);            // top diagonal
  b.add_line("1", "7", 302);            // through the inside: free
  b.add_line("1", "2", 303);            // coincides with a cube edge: kept once
  b.add_line("m1", "m2", 304);
  b.add_line("7", "far", 305);
  b.add_line("edge", "m2", 306);
  b.add_line("7", "5", 307);            // the same line again
  const SolidBuildResult r = b.build();
  ASSERT_TRUE(r.ok()) << all_messages(r);
  EXPECT_TRUE(r.diagnostics.empty()) << all_messages(r);
  const Solid& s = *r.solid;
  expect_valid_solid(s);
  EXPECT_TRUE(s.closed);  // lines do not open a solid
  ASSERT_EQ(s.edges.size(), 12u + 5u);
  EXPECT_EQ(count_kind(s, EdgeKind::Feature), 12u);
  auto kind_of = [&](VertexIndex a, VertexIndex c) {
    const SolidEdge* e = find_edge(s, a, c);
    return e ? e->kind : EdgeKind::Flat;
  };
  EXPECT_EQ(kind_of(4, 6), EdgeKind::Marking);
  EXPECT_EQ(find_edge(s, 4, 6)->left, 1);
  EXPECT_EQ(kind_of(0, 6), EdgeKind::Free);
  EXPECT_EQ(kind_of(8, 9), EdgeKind::Marking);
  EXPECT_EQ(kind_of(6, 10), EdgeKind::Free);
  EXPECT_EQ(kind_of(11, 9), EdgeKind::Marking);
  EXPECT_EQ(kind_of(0, 1), EdgeKind::Feature);
}

TEST(SolidBuilder, OnFaceLinesOfALoopAreMarkings) {
  // Fig. 31 of Desens: surface "A B G B C F G H" draws BG on the face; here on a square.
  SolidBuilder b;
  b.add_vertex("A", {0, 0, 0});
  b.add_vertex("B", {1, 0, 0});
  b.add_vertex("C", {2, 0, 0});
  b.add_vertex("F", {2, 2, 0});
  b.add_vertex("H", {0, 2, 0});
  b.add_vertex("G", {1, 1, 0});
  b.add_face_loop({"A", "B", "G", "B", "C", "F", "H"});
  const SolidBuildResult r = b.build();
  ASSERT_TRUE(r.ok()) << all_messages(r);
  const Solid& s = *r.solid;
  expect_valid_solid(s);
  ASSERT_EQ(s.faces[0].rings.size(), 1u);
  EXPECT_EQ(s.faces[0].rings[0].vertices.size(), 5u);
  ASSERT_EQ(s.edges.size(), 6u);
  EXPECT_EQ(s.edges[1].kind, EdgeKind::Marking);  // B–G, in loop order after A–B
  EXPECT_EQ(s.edges[1].v0, 1u);
  EXPECT_EQ(s.edges[1].v1, 5u);
}

TEST(SolidBuilder, EmptyAndDegenerateInputsDoNotCrash) {
  {
    const SolidBuildResult r = SolidBuilder().build();
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.solid->faces.empty());
    EXPECT_FALSE(r.solid->closed);
  }
  {  // only lines
    SolidBuilder b;
    b.add_vertex("a", {0, 0, 0});
    b.add_vertex("b", {1, 2, 3});
    b.add_line("a", "b");
    const SolidBuildResult r = b.build();
    ASSERT_TRUE(r.ok()) << all_messages(r);
    ASSERT_EQ(r.solid->edges.size(), 1u);
    EXPECT_EQ(r.solid->edges[0].kind, EdgeKind::Free);
    EXPECT_FALSE(r.solid->closed);
  }
  {  // faces naming nothing
    SolidBuilder b;
    b.add_vertex("x", {0, 0, 0});
    b.add_face({});
    b.add_face_loop({});
    b.add_face({"x"}, {{}});
    const SolidBuildResult r = b.build();
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(with_code(r, "too-few-vertices").size(), 4u) << all_messages(r);
  }
  {  // nonsense options
    SolidBuildOptions o;
    o.crease_angle_deg = std::nan("");
    o.planarity_tolerance = -1;
    const SolidBuildResult r = unit_cube({}, o).build();
    ASSERT_TRUE(r.ok()) << all_messages(r);
    EXPECT_EQ(count_kind(*r.solid, EdgeKind::Feature), 12u);
  }
}

// Random loops over a few coplanar points: the builder must never crash, and whatever it accepts must
// satisfy solid.hpp's contract.
TEST(SolidBuilder, RandomLoopsNeverBreakTheContract) {
  int accepted = 0;
  for (unsigned seed = 0; seed < 300; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> pick(0, 5), len(0, 9), coord(-3, 3);
    SolidBuilder b;
    for (int i = 0; i < 6; ++i) b.add_vertex(std::to_string(i), {double(coord(rng)), double(coord(rng)), 0});
    const int faces = len(rng) % 4;
    for (int f = 0; f < faces; ++f) {
      std::vector<std::string> loop;
      for (int k = len(rng); k > 0; --k) loop.push_back(std::to_string(pick(rng)));
      if (rng() % 2)
        b.add_face_loop(loop);
      else
        b.add_face(loop);
    }
    if (rng() % 2) b.add_line(std::to_string(pick(rng)), std::to_string(pick(rng)));
    const SolidBuildResult r = b.build();
    accepted += r.ok() && !r.solid->faces.empty();
    if (r.ok()) {
      SCOPED_TRACE(id("seed ", seed));
      expect_valid_solid(*r.solid);
    } else {
      EXPECT_FALSE(r.diagnostics.empty()) << "seed " << seed;
    }
  }
  EXPECT_GT(accepted, 10);  // the property is exercised on solids with faces, not only on rejections
}

}  // namespace
}  // namespace hlr
