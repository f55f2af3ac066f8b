// Mesh export (stdlib/mesh_export.hpp, issue 41): the files read back by a parser written here — counts,
// coordinates, closedness (every edge used once each way) and enclosed volume against the analytic value —
// for plain faces, faces with holes and concave faces, in OFF, OBJ and binary STL.
//   hlr_core_tests --gtest_filter='MeshExport*'
#include "stdlib/mesh_export.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/device/page/atomic_file.hpp"
#include "stdlib/generators.hpp"
#include "stdlib/shapes.hpp"

namespace hlr::test {
namespace {

namespace gen = hlr::stdlib;
using gen::MeshFormat;

// A mesh as read back: points and polygons (vertex numbers from 0), and OBJ's object names.
struct ReadMesh {
  std::vector<Point3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<std::string> objects;
  std::vector<Vector3> normals;  // STL's per triangle
};

ReadMesh read_off(const std::string& text) {
  std::istringstream in(text);
  ReadMesh m;
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "OFF");
  while (in.peek() == '#') std::getline(in, line);
  std::size_t v = 0, f = 0, e = 0;
  in >> v >> f >> e;
  for (std::size_t i = 0; i < v; ++i) {
    Point3 p;
    in >> p.x >> p.y >> p.z;
    m.points.push_back(p);
  }
  for (std::size_t i = 0; i < f; ++i) {
    std::size_t n = 0;
    in >> n;
    std::vector<std::size_t> poly(n);
    for (std::size_t& k : poly) in >> k;
    m.polygons.push_back(poly);
  }
  EXPECT_FALSE(in.fail());
  return m;
}

ReadMesh read_obj(const std::string& text) {
  std::istringstream in(text);
  ReadMesh m;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream l(line);
    std::string tag;
    l >> tag;
    if (tag == "v") {
      Point3 p;
      l >> p.x >> p.y >> p.z;
      m.points.push_back(p);
    } else if (tag == "f") {
      std::vector<std::size_t> poly;
      for (std::size_t k = 0; l >> k;) poly.push_back(k - 1);
      m.polygons.push_back(poly);
    } else if (tag == "o") {
      std::string name;
      l >> name;
      m.objects.push_back(name);
    }
  }
  return m;
}

float le_float(const std::string& bytes, std::size_t at) {
  std::uint32_t u = 0;
  for (int i = 0; i < 4; ++i)
    u |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]))
         << (8 * i);
  return std::bit_cast<float>(u);
}

ReadMesh read_stl(const std::string& bytes) {
  ReadMesh m;
  EXPECT_GE(bytes.size(), 84u);
  EXPECT_NE(bytes.substr(0, 5), "solid");
  std::uint32_t n = 0;
  for (int i = 0; i < 4; ++i)
    n |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[80 + static_cast<std::size_t>(i)]))
         << (8 * i);
  EXPECT_EQ(bytes.size(), 84 + 50 * std::size_t{n});
  // STL repeats each corner: equal floats are one vertex.
  std::map<std::array<float, 3>, std::size_t> index;
  for (std::size_t t = 0; t < n; ++t) {
    const std::size_t at = 84 + 50 * t;
    m.normals.push_back({le_float(bytes, at), le_float(bytes, at + 4), le_float(bytes, at + 8)});
    std::vector<std::size_t> poly;
    for (std::size_t c = 0; c < 3; ++c) {
      const std::array<float, 3> q{le_float(bytes, at + 12 + 12 * c), le_float(bytes, at + 16 + 12 * c),
                                   le_float(bytes, at + 20 + 12 * c)};
      const auto [it, added] = index.emplace(q, m.points.size());
      if (added) m.points.push_back({q[0], q[1], q[2]});
      poly.push_back(it->second);
    }
    m.polygons.push_back(poly);
  }
  return m;
}

// Every directed edge once and its reverse once: a closed, consistently oriented surface.
bool closed_and_oriented(const ReadMesh& m) {
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for (const auto& poly : m.polygons)
    for (std::size_t i = 0; i < poly.size(); ++i) ++directed[{poly[i], poly[(i + 1) % poly.size()]}];
  for (const auto& [edge, count] : directed) {
    if (count != 1) return false;
    const auto back = directed.find({edge.second, edge.first});
    if (back == directed.end() || back->second != 1) return false;
  }
  return !directed.empty();
}

// The divergence theorem over fans of each polygon (its own polygons are convex or triangles).
double enclosed_volume(const ReadMesh& m) {
  double v = 0;
  for (const auto& poly : m.polygons)
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
      const Vector3 a = to_vector(m.points[poly[0]]), b = to_vector(m.points[poly[i]]),
                    c = to_vector(m.points[poly[i + 1]]);
      v += dot(a, cross(b, c)) / 6;
    }
  return v;
}

Scene scene_of(std::vector<std::pair<std::string, Solid>> solids) {
  Scene scene;
  for (auto& [name, solid] : solids) scene.objects.emplace_back(name, std::move(solid));
  return scene;
}

TEST(MeshExport, BoxInEveryFormat) {
  const Scene scene = scene_of({{"box", gen::box({1, 2, 3}, {3, 5, 7})}});
  const ReadMesh off = read_off(gen::mesh_file_bytes(scene, MeshFormat::Off, "t"));
  EXPECT_EQ(off.points.size(), 8u);
  EXPECT_EQ(off.polygons.size(), 6u);  // quads stay quads
  EXPECT_TRUE(closed_and_oriented(off));
  EXPECT_DOUBLE_EQ(enclosed_volume(off), 2 * 3 * 4);
  const ReadMesh obj = read_obj(gen::mesh_file_bytes(scene, MeshFormat::Obj, "t"));
  EXPECT_EQ(obj.objects, std::vector<std::string>{"box"});
  EXPECT_TRUE(closed_and_oriented(obj));
  EXPECT_DOUBLE_EQ(enclosed_volume(obj), 24);
  const ReadMesh stl = read_stl(gen::mesh_file_bytes(scene, MeshFormat::Stl, "t"));
  EXPECT_EQ(stl.polygons.size(), 12u);
  EXPECT_EQ(stl.points.size(), 8u);
  EXPECT_TRUE(closed_and_oriented(stl));
  EXPECT_DOUBLE_EQ(enclosed_volume(stl), 24);
}

TEST(MeshExport, StlNormalsAreOutwardAndUnit) {
  const Scene scene = scene_of({{"c", gen::cylinder({0, 0, 0}, 2, 3, 7)}});
  const ReadMesh stl = read_stl(gen::mesh_file_bytes(scene, MeshFormat::Stl, "t"));
  ASSERT_FALSE(stl.polygons.empty());
  for (std::size_t t = 0; t < stl.polygons.size(); ++t) {
    const auto& p = stl.polygons[t];
    const Vector3 n = cross(stl.points[p[1]] - stl.points[p[0]], stl.points[p[2]] - stl.points[p[0]]);
    EXPECT_NEAR(length(stl.normals[t]), 1, 1e-6);
    EXPECT_GT(dot(n, stl.normals[t]), 0) << "triangle " << t << " winds against its normal";
  }
  EXPECT_TRUE(closed_and_oriented(stl));
  // A 7-sided prism: 7/2 r² sin(2π/7) h, to float precision.
  EXPECT_NEAR(enclosed_volume(stl), 3.5 * 4 * std::sin(2 * 3.14159265358979323846 / 7) * 3, 1e-5);
}

TEST(MeshExport, FacesWithHolesAreTriangulatedAndStayClosed) {
  // A 10 × 8 × 2 plate with a 2 × 2 square hole and an L-shaped (concave) hole through it.
  const std::vector<Point3> outline{{0, 0, 0}, {10, 0, 0}, {10, 8, 0}, {0, 8, 0}};
  const std::vector<std::vector<Point3>> holes{
      {{1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}},
      {{5, 2, 0}, {9, 2, 0}, {9, 3, 0}, {6, 3, 0}, {6, 6, 0}, {5, 6, 0}}};
  const Scene scene = scene_of({{"plate", gen::extrude(outline, {0, 0, 2}, holes)}});
  const double expected = (80 - 4 - (4 + 3)) * 2.0;
  for (const MeshFormat format : {MeshFormat::Off, MeshFormat::Obj, MeshFormat::Stl}) {
    const std::string bytes = gen::mesh_file_bytes(scene, format, "plate");
    const ReadMesh m = format == MeshFormat::Off   ? read_off(bytes)
                       : format == MeshFormat::Obj ? read_obj(bytes)
                                                   : read_stl(bytes);
    EXPECT_TRUE(closed_and_oriented(m)) << static_cast<int>(format);
    EXPECT_NEAR(enclosed_volume(m), expected, 1e-9) << static_cast<int>(format);
    for (const auto& poly : m.polygons) EXPECT_GE(poly.size(), 3u);
  }
}

TEST(MeshExport, ConcaveFacesInStlAreCutInsideThemselves) {
  // An L-shaped prism: its caps are concave hexagons, which a fan would cut across the notch.
  const std::vector<Point3> l{{0, 0, 0}, {4, 0, 0}, {4, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}};
  const Scene scene = scene_of({{"l", gen::extrude(l, {0, 0, 1})}});
  const ReadMesh stl = read_stl(gen::mesh_file_bytes(scene, MeshFormat::Stl, "l"));
  EXPECT_TRUE(closed_and_oriented(stl));
  EXPECT_NEAR(enclosed_volume(stl), 6, 1e-6);
  for (std::size_t t = 0; t < stl.polygons.size(); ++t) {
    const auto& p = stl.polygons[t];
    const Vector3 n = cross(stl.points[p[1]] - stl.points[p[0]], stl.points[p[2]] - stl.points[p[0]]);
    EXPECT_GT(dot(n, stl.normals[t]), 0) << "triangle " << t;
  }
}

TEST(MeshExport, SeveralSolidsNumberThroughTheFileAndFacelessOnesAreLeftOut) {
  Solid lines;  // free lines only: no surface
  lines.vertices = {{0, 0, 0}, {1, 1, 1}};
  lines.edges.push_back(SolidEdge{0, 1, kNoFace, kNoFace, EdgeKind::Free, false});
  const Scene scene = scene_of({{"first one", gen::box({0, 0, 0}, {1, 1, 1})},
                                {"wire", std::move(lines)},
                                {"second", gen::box({5, 0, 0}, {6, 2, 1})}});
  const ReadMesh obj = read_obj(gen::mesh_file_bytes(scene, MeshFormat::Obj, "two"));
  EXPECT_EQ(obj.objects, (std::vector<std::string>{"first_one", "second"}));
  EXPECT_EQ(obj.points.size(), 16u);
  EXPECT_TRUE(closed_and_oriented(obj));
  EXPECT_DOUBLE_EQ(enclosed_volume(obj), 1 + 2);
  const ReadMesh off = read_off(gen::mesh_file_bytes(scene, MeshFormat::Off, "two"));
  EXPECT_EQ(off.points.size(), 16u);
  EXPECT_DOUBLE_EQ(enclosed_volume(off), 3);
}

TEST(MeshExport, MarkedBoxWritesOnlyItsSurfaceVertices) {
  const Scene scene = scene_of({{"m", gen::marked_box({0, 0, 0}, {2, 2, 2})}});
  const ReadMesh off = read_off(gen::mesh_file_bytes(scene, MeshFormat::Off, "m"));
  EXPECT_EQ(off.points.size(), 8u);  // the X's and the mast's ends are on no face
  EXPECT_TRUE(closed_and_oriented(off));
}

TEST(MeshExport, CoordinatesReadBackExactly) {
  const double x = 0.1, y = 1.0 / 3, z = -2.718281828459045;
  const Scene scene = scene_of({{"b", gen::box({x, y, z}, {x + 0.7, y + 10, z + 0.3})}});
  const ReadMesh off = read_off(gen::mesh_file_bytes(scene, MeshFormat::Off, "b"));
  bool found = false;
  for (const Point3& p : off.points) found |= (p.x == x && p.y == y && p.z == z);
  EXPECT_TRUE(found);
}

TEST(MeshExport, NonFiniteVertexIsRefused) {
  Solid s = gen::box({0, 0, 0}, {1, 1, 1});
  s.vertices[0].x = std::numeric_limits<double>::infinity();
  const Scene scene = scene_of({{"bad", std::move(s)}});
  EXPECT_THROW(gen::mesh_file_bytes(scene, MeshFormat::Off, "x"), DeviceError);
}

}  // namespace
}  // namespace hlr::test
