// Helpers for the solid test suites: small solids, an invariant checker written from solid.hpp's
// contract (not from the builder's code), and diagnostic lookup.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/solid/solid.hpp"
#include "core/solid/solid_builder.hpp"

namespace hlr::solid_test {

// prefix + number, built in place (GCC 12 warns falsely, -Wrestrict, on "text" + std::to_string(i)).
inline std::string id(const std::string& prefix, long number) {
  std::string s = prefix;
  s += std::to_string(number);
  return s;
}

// Unit cube [0,1]³, vertices "1".."8"; faces in the order bottom, top, front (y=0), back, left (x=0),
// right, each counter-clockwise seen from outside unless listed in `clockwise` (0-based face numbers).
inline SolidBuilder unit_cube(std::set<int> clockwise = {}, SolidBuildOptions options = {}) {
  SolidBuilder b(options);
  const Point3 p[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int i = 0; i < 8; ++i) b.add_vertex(std::to_string(i + 1), p[i], 100 + i);
  const std::vector<std::vector<std::string>> faces = {{"1", "4", "3", "2"}, {"5", "6", "7", "8"},
                                                       {"1", "2", "6", "5"}, {"3", "4", "8", "7"},
                                                       {"1", "5", "8", "4"}, {"2", "3", "7", "6"}};
  for (int f = 0; f < 6; ++f) {
    std::vector<std::string> ring = faces[static_cast<std::size_t>(f)];
    if (clockwise.contains(f)) std::reverse(ring.begin(), ring.end());
    b.add_face(ring, {}, 200 + f);
  }
  return b;
}

// Signed volume by the divergence theorem over all rings.
inline double signed_volume(const Solid& s) {
  double six = 0;
  for (const Face& f : s.faces)
    for (const Ring& r : f.rings)
      for (std::size_t i = 1; i + 1 < r.vertices.size(); ++i) {
        const Vector3 a = to_vector(s.vertices[r.vertices[0]]), b = to_vector(s.vertices[r.vertices[i]]),
                      c = to_vector(s.vertices[r.vertices[i + 1]]);
        six += dot(a, cross(b, c));
      }
  return six / 6;
}

inline std::size_t count_kind(const Solid& s, EdgeKind kind) {
  return static_cast<std::size_t>(
      std::count_if(s.edges.begin(), s.edges.end(), [&](const SolidEdge& e) { return e.kind == kind; }));
}

inline std::size_t count_concave(const Solid& s) {
  return static_cast<std::size_t>(
      std::count_if(s.edges.begin(), s.edges.end(), [](const SolidEdge& e) { return e.concave; }));
}

inline const SolidEdge* find_edge(const Solid& s, VertexIndex a, VertexIndex b) {
  for (const SolidEdge& e : s.edges)
    if ((e.v0 == a && e.v1 == b) || (e.v0 == b && e.v1 == a)) return &e;
  return nullptr;
}

inline std::vector<const SolidDiagnostic*> with_code(const SolidBuildResult& r, const std::string& code) {
  std::vector<const SolidDiagnostic*> out;
  for (const SolidDiagnostic& d : r.diagnostics)
    if (d.code == code) out.push_back(&d);
  return out;
}

inline std::string all_messages(const SolidBuildResult& r) {
  std::string s;
  for (const SolidDiagnostic& d : r.diagnostics) s += "[" + d.code + "] " + d.message + "\n";
  return s;
}

// The contract of solid.hpp, checked from the outside. `off_plane` bounds the distance of ring vertices
// from their face's plane (loosened only for the thesis's warped faces).
inline void expect_valid_solid(const Solid& s, double off_plane = 1e-6) {
  ASSERT_EQ(s.planes.size(), s.faces.size());
  // Directed ring edges → faces traversing them.
  std::map<std::pair<VertexIndex, VertexIndex>, std::vector<FaceIndex>> directed;
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    const Face& face = s.faces[f];
    ASSERT_FALSE(face.rings.empty()) << "face " << f;
    const Vector3 n = s.planes[f].normal;
    EXPECT_NEAR(length(n), 1, 1e-12) << "face " << f;
    EXPECT_GT(dot(newell_normal(s.vertices, face.rings[0]), n), 0) << "outer ring of face " << f << " not CCW";
    for (std::size_t k = 1; k < face.rings.size(); ++k)
      EXPECT_LT(dot(newell_normal(s.vertices, face.rings[k]), n), 0) << "hole " << k << " of face " << f;
    for (const Ring& r : face.rings) {
      for (VertexIndex v : r.vertices) EXPECT_NEAR(s.planes[f].signed_distance(s.vertices[v]), 0, off_plane);
      for (std::size_t i = 0; i < r.vertices.size(); ++i)
        directed[{r.vertices[i], r.vertices[(i + 1) % r.vertices.size()]}].push_back(static_cast<FaceIndex>(f));
    }
  }
  auto traverses = [&](FaceIndex f, VertexIndex a, VertexIndex b) {
    const auto it = directed.find({a, b});
    return it != directed.end() && std::find(it->second.begin(), it->second.end(), f) != it->second.end();
  };
  std::set<std::pair<VertexIndex, VertexIndex>> seen;
  for (const SolidEdge& e : s.edges) {
    EXPECT_TRUE(seen.insert(std::minmax(e.v0, e.v1)).second) << "edge " << e.v0 << "-" << e.v1 << " twice";
    switch (e.kind) {
      case EdgeKind::Free:
        EXPECT_EQ(e.left, kNoFace);
        EXPECT_EQ(e.right, kNoFace);
        break;
      case EdgeKind::Marking:
      case EdgeKind::Hatch:
        EXPECT_NE(e.left, kNoFace);
        EXPECT_EQ(e.left, e.right);
        break;
      case EdgeKind::Boundary:
        EXPECT_EQ(e.right, kNoFace);
        EXPECT_TRUE(traverses(e.left, e.v0, e.v1)) << "boundary edge " << e.v0 << "-" << e.v1;
        break;
      default:
        EXPECT_TRUE(traverses(e.left, e.v0, e.v1)) << "left of " << e.v0 << "-" << e.v1;
        EXPECT_TRUE(traverses(e.right, e.v1, e.v0)) << "right of " << e.v0 << "-" << e.v1;
    }
  }
  // Every ring edge is in the table; a closed solid has each directed edge matched by its reverse.
  for (const auto& [ab, fs] : directed) {
    EXPECT_TRUE(seen.contains(std::minmax(ab.first, ab.second))) << "ring edge " << ab.first << "-" << ab.second;
    if (s.closed) {
      EXPECT_EQ(fs.size(), 1u);
      EXPECT_TRUE(directed.contains({ab.second, ab.first})) << "closed solid with open edge";
    }
  }
}

}  // namespace hlr::solid_test
