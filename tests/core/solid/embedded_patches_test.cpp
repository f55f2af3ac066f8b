// Patches of triangles certified not to pass through each other (core/solid/embedded_patches.hpp): the
// certificate on hand-made cases (a flat sheet, a sheet with a hole, a fan wound twice round its vertex, a
// strip spiralling over itself, a sheet folded back), and on random folded sheets and bumpy meshes the
// claim itself, checked pair by pair by a different means: every two triangles of one patch, projected
// along its axis, have disjoint interiors (a separating edge, exact orientations).
//   hlr_core_tests --gtest_filter='EmbeddedPatches*'
#include "core/solid/embedded_patches.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/geometry/exact_predicates.hpp"
#include "core/solid/solid_builder.hpp"
#include "stdlib/generators.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::test {
namespace {

Solid build(const std::vector<Point3>& points, const std::vector<std::vector<VertexIndex>>& triangles) {
  SolidBuilder builder;
  for (Point3 p : points) builder.add_vertex(p);
  for (const auto& t : triangles) builder.add_indexed_face_loop(t);
  SolidBuildResult built = builder.build();
  for (const auto& d : built.diagnostics) ADD_FAILURE() << d.message;
  if (!built.ok()) throw std::runtime_error("the test mesh does not build");
  return std::move(*built.solid);
}

std::vector<FaceIndex> all_faces(const Solid& s) {
  std::vector<FaceIndex> f(s.faces.size());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = static_cast<FaceIndex>(i);
  return f;
}

// An nx × ny sheet of squares split in two, z = height(x, y), x and y moved by shift(x, y).
template <typename Height, typename Shift>
Solid sheet(int nx, int ny, Height&& height, Shift&& shift,
            std::vector<std::vector<VertexIndex>>* faces_out = nullptr) {
  std::vector<Point3> points;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double x = i, y = j;
      const Vector3 d = shift(x, y);
      points.push_back({x + d.x, y + d.y, height(x, y)});
    }
  auto at = [&](int i, int j) { return static_cast<VertexIndex>(j * (nx + 1) + i); };
  std::vector<std::vector<VertexIndex>> faces;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  if (faces_out) *faces_out = faces;
  return build(points, faces);
}

TEST(EmbeddedPatches, AFlatSheetIsOnePatchAlongItsNormal) {
  const Solid s = sheet(
      6, 5, [](double, double) { return 0.0; }, [](double, double) { return Vector3{}; });
  const std::vector<FaceIndex> faces = all_faces(s);
  EXPECT_TRUE(projects_one_to_one(s, faces, 2));
  EXPECT_FALSE(projects_one_to_one(s, faces, 0));  // seen edge on: every triangle flat
  const std::vector<std::uint32_t> patch = embedded_patches(s);
  for (std::uint32_t p : patch) EXPECT_EQ(p, patch[0]);
  EXPECT_NE(patch[0], kNoPatch);
}

TEST(EmbeddedPatches, ASheetWithAHoleHasAnOutlineAndAHole) {
  std::vector<std::vector<VertexIndex>> faces;
  sheet(
      4, 4, [](double, double) { return 0.0; }, [](double, double) { return Vector3{}; }, &faces);
  // Without the two triangles of the middle square (1, 1)–(2, 2): the border is two loops.
  Solid full = sheet(
      4, 4, [](double, double) { return 0.0; }, [](double, double) { return Vector3{}; });
  std::vector<FaceIndex> kept;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (f / 2 != 1 * 4 + 1) kept.push_back(static_cast<FaceIndex>(f));
  EXPECT_TRUE(projects_one_to_one(full, kept, 2));
  // Two squares apart, touching at one corner: the border passes that vertex twice.
  const std::vector<FaceIndex> corner_to_corner{0, 1, 2 * (1 * 4 + 1), 2 * (1 * 4 + 1) + 1};
  EXPECT_FALSE(projects_one_to_one(full, corner_to_corner, 2));
}

// Twelve triangles round a vertex whose far corners go twice round it, up on the first turn and down on
// the second: every triangle turns the same way seen from above, yet the fan passes through itself.
TEST(EmbeddedPatches, AFanWoundTwiceIsRefused) {
  std::vector<Point3> points{{0, 0, 0}};
  constexpr int kCorners = 12;
  for (int k = 0; k < kCorners; ++k) {
    const double angle = 4 * std::numbers::pi * k / kCorners;
    points.push_back({std::cos(angle), std::sin(angle), std::cos(angle / 2 + 0.3)});
  }
  std::vector<std::vector<VertexIndex>> faces;
  for (int k = 0; k < kCorners; ++k)
    faces.push_back({0, static_cast<VertexIndex>(1 + k), static_cast<VertexIndex>(1 + (k + 1) % kCorners)});
  const Solid s = build(points, faces);
  const std::vector<FaceIndex> all = all_faces(s);
  for (int axis = 0; axis < 3; ++axis) EXPECT_FALSE(projects_one_to_one(s, all, axis)) << axis;
  // One turn of it is fine.
  const std::vector<FaceIndex> half(all.begin(), all.begin() + kCorners / 2);
  EXPECT_TRUE(projects_one_to_one(s, half, 2));
  // Neither is any patch grown over it: a patch holds faces that cannot cross.
  const std::vector<std::uint32_t> patch = embedded_patches(s);
  for (int k = 0; k < kCorners / 2; ++k)
    EXPECT_FALSE(patch[k] != kNoPatch && patch[k] == patch[k + kCorners / 2]) << k;
}

// A strip climbing one and a half turns: nothing crosses, but seen from above it lies over itself, which
// the certificate cannot tell from a crossing; a sheet folded back over itself likewise.
TEST(EmbeddedPatches, OverlapsInProjectionAreRefused) {
  std::vector<Point3> points;
  std::vector<std::vector<VertexIndex>> faces;
  constexpr int kSteps = 36;
  for (int k = 0; k <= kSteps; ++k) {
    const double angle = 3 * std::numbers::pi * k / kSteps, z = 0.3 * k;
    points.push_back({std::cos(angle), std::sin(angle), z});
    points.push_back({2 * std::cos(angle), 2 * std::sin(angle), z});
  }
  for (VertexIndex k = 0; k < kSteps; ++k) {
    faces.push_back({2 * k, 2 * k + 1, 2 * k + 3});
    faces.push_back({2 * k, 2 * k + 3, 2 * k + 2});
  }
  const Solid spiral = build(points, faces);
  EXPECT_FALSE(projects_one_to_one(spiral, all_faces(spiral), 2));
  // Short of one turn (24 steps) it lies beside itself.
  std::vector<FaceIndex> first(2 * 22);
  for (std::size_t f = 0; f < first.size(); ++f) first[f] = static_cast<FaceIndex>(f);
  EXPECT_TRUE(projects_one_to_one(spiral, first, 2));

  // x runs 0 … 4 and back to 1, one unit higher on the way back.
  const Solid folded = sheet(
      8, 2, [](double x, double) { return x > 4 ? 1.0 : 0.0; },
      [](double x, double) {
        return Vector3{x > 4 ? 8 - 2 * x : 0.0, 0, 0};
      });
  EXPECT_FALSE(projects_one_to_one(folded, all_faces(folded), 2));

  // One inner vertex pushed past its neighbour: the outline is untouched, but the triangles round the
  // vertex fold over each other, some of them turned over in projection.
  const Solid pushed = sheet(
      4, 4, [](double, double) { return 0.0; },
      [](double x, double y) {
        return x == 2 && y == 2 ? Vector3{1.5, 0.2, 0.3} : Vector3{};
      });
  EXPECT_FALSE(projects_one_to_one(pushed, all_faces(pushed), 2));
}

// Whether triangles a and b of s, projected along `axis`, have disjoint interiors: some edge line of one
// has the other wholly on its outer closed side (both turn the same way in the projection).
bool apart_in_projection(const Solid& s, FaceIndex a, FaceIndex b, int axis) {
  auto project = [&](VertexIndex v) {
    const Point3 p = s.vertices[v];
    return axis == 0 ? Point2{p.y, p.z} : (axis == 1 ? Point2{p.z, p.x} : Point2{p.x, p.y});
  };
  Point2 t[2][3];
  for (int k = 0; k < 3; ++k) {
    t[0][k] = project(s.faces[a].rings[0].vertices[k]);
    t[1][k] = project(s.faces[b].rings[0].vertices[k]);
  }
  for (int which = 0; which < 2; ++which) {
    const int turn = orient2d(t[which][0], t[which][1], t[which][2]);
    for (int k = 0; k < 3; ++k) {
      bool outside = true;
      for (int m = 0; m < 3 && outside; ++m)
        outside = orient2d(t[which][k], t[which][(k + 1) % 3], t[1 - which][m]) * turn <= 0;
      if (outside) return true;
    }
  }
  return false;
}

// The claim, pair by pair: in each patch (its axis that of its first face's normal, as it was grown),
// every two triangles are apart in projection — so no two cross.
void expect_patches_sound(const Solid& s, double min_share) {
  const std::vector<std::uint32_t> patch = embedded_patches(s);
  std::map<std::uint32_t, std::vector<FaceIndex>> members;
  for (std::size_t f = 0; f < patch.size(); ++f)
    if (patch[f] != kNoPatch) members[patch[f]].push_back(static_cast<FaceIndex>(f));
  std::size_t covered = 0;
  for (const auto& [id, faces] : members) {
    covered += faces.size();
    const Vector3 n = s.planes[id].normal;
    const double along[3] = {std::abs(n.x), std::abs(n.y), std::abs(n.z)};
    const int axis = static_cast<int>(std::max_element(along, along + 3) - along);
    EXPECT_TRUE(projects_one_to_one(s, faces, axis));
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (std::size_t j = i + 1; j < faces.size(); ++j)
        ASSERT_TRUE(apart_in_projection(s, faces[i], faces[j], axis))
            << "faces " << faces[i] << " and " << faces[j] << " of patch " << id;
  }
  EXPECT_GE(static_cast<double>(covered), min_share * static_cast<double>(s.faces.size()));
}

TEST(EmbeddedPatches, EveryPatchOfAFoldedSheetIsApartPairByPair) {
  for (unsigned seed = 0; seed < 12; ++seed) {
    SCOPED_TRACE(seed);
    Rng r(seed);
    // Bumps, and a few vertices pushed far sideways: folds, flips and overlaps in every direction.
    std::vector<std::array<double, 4>> pushes;
    for (int k = 0; k < 5; ++k) pushes.push_back({r(0, 24), r(0, 24), r(-3, 3), r(-3, 3)});
    const Solid s = sheet(
        24, 24,
        [&](double x, double y) {
          return 2 * std::sin(0.4 * x) * std::cos(0.3 * y) + 0.05 * std::sin(7 * x * y);
        },
        [&](double x, double y) {
          Vector3 d{};
          for (const auto& p : pushes) {
            const double w = std::exp(-((x - p[0]) * (x - p[0]) + (y - p[1]) * (y - p[1])));
            d = d + Vector3{w * p[2], w * p[3], 0};
          }
          return d;
        });
    expect_patches_sound(s, 0.5);
  }
}

TEST(EmbeddedPatches, AWideWavySheetGrowsPatchesOfThousandsOfFaces) {
  // 2 160 triangles facing up: patches grow past 512 faces (the size they stopped at before stop 48),
  // and every pair in them is still apart in projection.
  const Solid s = sheet(
      36, 30, [](double x, double y) { return 1.5 * std::sin(0.25 * x) + std::cos(0.2 * y); },
      [](double, double) { return Vector3{}; });
  expect_patches_sound(s, 0.99);
  const std::vector<std::uint32_t> patch = embedded_patches(s);
  std::map<std::uint32_t, std::size_t> size;
  for (std::uint32_t p : patch)
    if (p != kNoPatch) ++size[p];
  std::size_t largest = 0;
  for (const auto& [id, count] : size) largest = std::max(largest, count);
  EXPECT_GT(largest, 1024u);
}

TEST(EmbeddedPatches, EveryPatchOfABumpyMeshIsApartPairByPair) {
  for (unsigned seed = 0; seed < 4; ++seed) {
    SCOPED_TRACE(seed);
    expect_patches_sound(stdlib::closed_mesh(1000 + 1500 * static_cast<int>(seed), seed), 0.9);
  }
}

}  // namespace
}  // namespace hlr::test
