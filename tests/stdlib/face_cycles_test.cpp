// Faces told apart by their cycles of vertices (stdlib/face_cycles.hpp): the canonical cycle reads the
// same for every rotation and both directions, and any_repeated_cycle agrees with a map of canonical
// cycles, including where the hashes agree and the cycles do not. An import of a large mesh with one
// face repeated still drops it and says so, in the file's terms.
#include "stdlib/face_cycles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "stdlib/mesh_import.hpp"

namespace hlr::stdlib::mesh_detail {
namespace {

std::vector<std::uint32_t> canonical(const std::vector<std::uint32_t>& ring) {
  std::vector<std::uint32_t> out;
  canonical_cycle(ring, out);
  return out;
}

TEST(FaceCycles, CanonicalFormOfEveryRotationAndDirection) {
  const std::vector<std::uint32_t> ring = {7, 3, 9, 4, 12};
  const std::vector<std::uint32_t> expected = {3, 7, 12, 4, 9};  // from 3, towards the smaller neighbour
  for (std::size_t r = 0; r < ring.size(); ++r) {
    std::vector<std::uint32_t> turned = ring;
    std::rotate(turned.begin(), turned.begin() + static_cast<std::ptrdiff_t>(r), turned.end());
    EXPECT_EQ(canonical(turned), expected);
    std::reverse(turned.begin(), turned.end());
    EXPECT_EQ(canonical(turned), expected);
  }
  EXPECT_NE(canonical({1, 2, 3, 4}), canonical({1, 3, 2, 4}));  // the same vertices, another cycle
}

// The triangles' shortcut hashes what the general path does: the canonical cycle's hash, for every order
// of three distinct vertices (the two directions of a triangle are one cycle).
TEST(FaceCycles, TriangleHashIsTheCanonicalCyclesHash) {
  std::mt19937 rng(4242);
  std::uniform_int_distribution<std::uint32_t> vertex(0, 1000);
  for (int i = 0; i < 2000; ++i) {
    std::vector<std::uint32_t> t = {vertex(rng), vertex(rng), vertex(rng)};
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
    const std::uint64_t expected = cycle_hash(canonical(t));
    std::sort(t.begin(), t.end());
    do {
      ASSERT_EQ(triangle_cycle_hash(t[0], t[1], t[2]), expected) << t[0] << " " << t[1] << " " << t[2];
    } while (std::next_permutation(t.begin(), t.end()));
  }
  EXPECT_NE(triangle_cycle_hash(1, 2, 3), triangle_cycle_hash(1, 2, 4));
}

// Random faces of 3–6 vertices out of a few hundred, their canonical cycles counted in a map.
struct Faces {
  std::vector<std::vector<std::uint32_t>> rings;
  std::vector<std::uint64_t> hashes;
  bool repeated() const {
    std::map<std::vector<std::uint32_t>, int> seen;
    for (const auto& r : rings)
      if (seen[canonical(r)]++ > 0) return true;
    return false;
  }
  bool same(std::size_t a, std::size_t b) const { return canonical(rings[a]) == canonical(rings[b]); }
};

Faces random_faces(std::mt19937_64& rng, std::size_t count) {
  std::uniform_int_distribution<std::uint32_t> vertex(0, 400), size(3, 6);
  Faces faces;
  while (faces.rings.size() < count) {
    std::vector<std::uint32_t> ring;
    const std::uint32_t n = size(rng);
    while (ring.size() < n) {
      const std::uint32_t v = vertex(rng);
      if (std::find(ring.begin(), ring.end(), v) == ring.end()) ring.push_back(v);
    }
    faces.rings.push_back(ring);
  }
  for (const auto& r : faces.rings) faces.hashes.push_back(cycle_hash(canonical(r)));
  return faces;
}

TEST(FaceCycles, RepeatedCycleFoundAsAMapFindsIt) {
  std::mt19937_64 rng(42);
  for (int trial = 0; trial < 20; ++trial) {
    Faces faces = random_faces(rng, 20000);
    if (trial % 2 == 1) {  // plant one repeat: an earlier face, turned and reversed, somewhere later
      std::uniform_int_distribution<std::size_t> at(0, faces.rings.size() - 1);
      std::size_t from = at(rng), to = at(rng);
      if (from > to) std::swap(from, to);
      if (from == to) to = from + 1;
      std::vector<std::uint32_t> copy = faces.rings[from];
      std::rotate(copy.begin(), copy.begin() + 1, copy.end());
      std::reverse(copy.begin(), copy.end());
      faces.rings[to] = copy;
      faces.hashes[to] = cycle_hash(canonical(copy));
    }
    const bool expected = faces.repeated();
    EXPECT_EQ(
        any_repeated_cycle(faces.hashes, [&](std::size_t a, std::size_t b) { return faces.same(a, b); }),
        expected)
        << "trial " << trial;
    if (trial % 2 == 1) {
      EXPECT_TRUE(expected);
    }
  }
}

// Every hash the same (as if all collided): the cycles decide.
TEST(FaceCycles, EqualHashesAreCheckedAgainstTheCycles) {
  std::mt19937_64 rng(7);
  Faces faces = random_faces(rng, 300);
  faces.rings.erase(std::unique(faces.rings.begin(), faces.rings.end()), faces.rings.end());
  std::map<std::vector<std::uint32_t>, int> seen;
  std::vector<std::vector<std::uint32_t>> distinct;
  for (const auto& r : faces.rings)
    if (seen[canonical(r)]++ == 0) distinct.push_back(r);
  faces.rings = distinct;
  faces.hashes.assign(faces.rings.size(), 0x123456789abcdefull);
  auto same = [&](std::size_t a, std::size_t b) { return faces.same(a, b); };
  EXPECT_FALSE(any_repeated_cycle(faces.hashes, same));
  faces.rings.push_back(faces.rings[5]);
  faces.hashes.push_back(faces.hashes[5]);
  EXPECT_TRUE(any_repeated_cycle(faces.hashes, same));
}

// An OFF grid of 2·60·60 triangles (more than the import passes on as read), with one triangle repeated,
// wound the other way, near the end: dropped, and named by its number and line as for a small mesh.
TEST(FaceCycles, LargeImportStillDropsARepeatedFace) {
  constexpr int kSide = 61;  // vertices a side
  std::string text = "OFF\n" + std::to_string(kSide * kSide) + " " +
                     std::to_string(2 * (kSide - 1) * (kSide - 1) + 1) + " 0\n";
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) text += std::to_string(x) + " " + std::to_string(y) + " 0\n";
  int faces = 0;
  for (int y = 0; y + 1 < kSide; ++y)
    for (int x = 0; x + 1 < kSide; ++x) {
      const int v = y * kSide + x;
      text +=
          "3 " + std::to_string(v) + " " + std::to_string(v + 1) + " " + std::to_string(v + kSide + 1) + "\n";
      text += "3 " + std::to_string(v) + " " + std::to_string(v + kSide + 1) + " " +
              std::to_string(v + kSide) + "\n";
      faces += 2;
    }
  text += "3 " + std::to_string(kSide + 1) + " 1 0\n";  // face 1 (0, 1, kSide + 1), reversed
  const int line = 2 + kSide * kSide + faces + 1;
  const ImportedMesh m = import_off(text, "grid.off");
  EXPECT_EQ(m.solid.faces.size(), static_cast<std::size_t>(faces));
  const std::string message = "face " + std::to_string(faces + 1) + " repeats face 1; dropped it";
  const auto found = std::find_if(m.warnings.begin(), m.warnings.end(),
                                  [&](const MeshProblem& p) { return p.message == message; });
  ASSERT_NE(found, m.warnings.end()) << message;
  EXPECT_EQ(found->line, line);
}

}  // namespace
}  // namespace hlr::stdlib::mesh_detail
