// The welding index (stdlib/mesh_detail.hpp): a point's first index, found by exact coordinates with -0
// and +0 equal, against a std::map of the coordinates' bit patterns — on 270 000 points with repeats (some
// with a zero's sign flipped), in a table sized for them and in one grown from its smallest size (growing
// rehashes through the caller's points), and on points one ulp apart.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <vector>

#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib {
namespace {

using mesh_detail::ExactPointIndex;
using Bits = std::array<std::uint64_t, 3>;

Bits bits_of(Point3 p) {
  auto canonical = [](double v) { return std::bit_cast<std::uint64_t>(v == 0 ? 0.0 : v); };
  return {canonical(p.x), canonical(p.y), canonical(p.z)};
}

// Inserts `points` in order, each with its own index, and checks every answer against the reference.
void expect_first_indices(const std::vector<Point3>& points, std::size_t expected) {
  ExactPointIndex index(expected);
  std::map<Bits, std::uint32_t> first;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto fresh = static_cast<std::uint32_t>(i);
    const std::uint32_t got = index.insert(points[i], fresh, [&](std::uint32_t k) { return points[k]; });
    const auto [it, added] = first.try_emplace(bits_of(points[i]), fresh);
    ASSERT_EQ(got, it->second) << "point " << i;
  }
}

TEST(ExactPointIndex, FindsEachPointsFirstIndexAmongManyDistinctOnes) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  std::vector<Point3> points;
  for (int i = 0; i < 200000; ++i) points.push_back({coordinate(rng), coordinate(rng), coordinate(rng)});
  // Repeats of earlier points, some with a zero coordinate's sign flipped.
  for (int i = 0; i < 50000; ++i) {
    Point3 p = points[rng() % points.size()];
    if (i % 5 == 0) p.y = 0.0;
    points.push_back(p);
  }
  for (int i = 0; i < 20000; ++i) {
    Point3 p = points[200000 + rng() % 50000];
    if (p.y == 0) p.y = i % 2 == 0 ? -0.0 : 0.0;
    points.push_back(p);
  }
  expect_first_indices(points, points.size());
  expect_first_indices(points, 0);  // grown from 16 slots
}

TEST(ExactPointIndex, TellsApartPointsOneUlpApartAndWeldsSignedZeros) {
  std::vector<Point3> points;
  const double one_up = std::nextafter(1.0, 2.0);
  points.push_back({1, 0, 0});
  points.push_back({one_up, 0, 0});
  points.push_back({1, -0.0, 0});
  points.push_back({1, 0, -0.0});
  points.push_back({-0.0, -0.0, -0.0});
  points.push_back({0, 0, 0});
  points.push_back({std::numeric_limits<double>::denorm_min(), 0, 0});
  expect_first_indices(points, 0);
  ExactPointIndex index;
  auto at = [&](std::uint32_t k) { return points[k]; };
  for (std::uint32_t i = 0; i < points.size(); ++i) index.insert(points[i], i, at);
  EXPECT_EQ(index.insert({1, 0, 0}, 99, at), 0u);
  EXPECT_EQ(index.insert({one_up, -0.0, 0}, 99, at), 1u);
  EXPECT_EQ(index.insert({0, -0.0, 0}, 99, at), 4u);
  EXPECT_EQ(index.insert({std::numeric_limits<double>::denorm_min(), 0, 0}, 99, at), 6u);
}

}  // namespace
}  // namespace hlr::stdlib
