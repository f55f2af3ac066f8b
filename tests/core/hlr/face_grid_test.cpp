// The frame's grid of occluders (core/hlr/face_grid.hpp): an edge meets every occluder whose outline it
// crosses and that lies nearer than the edge's farthest point, once each, and none that lies behind it by
// more than a float's rounding — checked against every occluder, one by one, on random triangles and
// segments.
#include "core/hlr/face_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace hlr {
namespace {

double orient(Point2 a, Point2 b, Point2 c) { return cross(b - a, c - a); }

// Whether segment a→b meets triangle t (inside, or crossing a side), in doubles: random data keeps away
// from the borderline cases, where the grid's margin takes in more anyway.
bool meets(const Point2* t, Point2 a, Point2 b) {
  auto inside = [&](Point2 p) {
    const double d0 = orient(t[0], t[1], p), d1 = orient(t[1], t[2], p), d2 = orient(t[2], t[0], p);
    return (d0 >= 0 && d1 >= 0 && d2 >= 0) || (d0 <= 0 && d1 <= 0 && d2 <= 0);
  };
  if (inside(a) || inside(b)) return true;
  for (int i = 0; i < 3; ++i) {
    const Point2 p = t[i], q = t[(i + 1) % 3];
    if (orient(a, b, p) * orient(a, b, q) <= 0 && orient(p, q, a) * orient(p, q, b) <= 0) return true;
  }
  return false;
}

// Random triangles over a 10 × 10 picture, of sizes from a hundredth to a third of it, at depths that
// are not floats (so that the grid's rounding to floats is tested).
FrameSetup random_triangles(std::mt19937_64& rng, std::size_t count) {
  std::uniform_real_distribution<double> at(0, 10), size(0.1, 3), depth(1, 5), unit(-1, 1);
  FrameSetup setup;
  for (std::size_t i = 0; i < count; ++i) {
    const Point2 c{at(rng), at(rng)};
    const double s = size(rng) * (i % 7 == 0 ? 1 : 0.05);
    Occluder o;
    o.face = static_cast<FaceIndex>(i);
    o.first_point = static_cast<std::uint32_t>(setup.polygon_points.size());
    o.first_ring = static_cast<std::uint32_t>(setup.ring_ends.size());
    o.ring_count = 1;
    o.min_depth = depth(rng);
    o.picture_tolerance = 1e-12;
    for (int k = 0; k < 3; ++k) {
      const Point2 p{c.x + s * unit(rng), c.y + s * unit(rng)};
      setup.polygon_points.push_back(p);
      setup.polygon_seams.push_back(kNoFace);
      o.bounds.include(p);
    }
    setup.ring_ends.push_back(static_cast<std::uint32_t>(setup.polygon_points.size()));
    setup.occluders.push_back(o);
  }
  return setup;
}

// The occluders the grid has segment a→b meet, in the order met.
std::vector<std::uint32_t> met(const FaceGrid& grid, Point2 a, Point2 b, double max_depth,
                               std::vector<std::uint32_t>& stamp, std::uint32_t mark) {
  std::vector<std::uint32_t> ids;
  grid.for_each_near(a, b, max_depth, stamp, mark, [&](std::uint32_t id) { ids.push_back(id); });
  return ids;
}

TEST(FaceGrid, MeetsEveryNearerOccluderCrossedOnceAndNoneBehind) {
  std::mt19937_64 rng(20261207);
  const FrameSetup setup = random_triangles(rng, 4000);
  const Rect2 domain{0, 0, 10, 10};
  const FaceGrid grid(setup, domain, 1);
  std::vector<std::uint32_t> stamp(setup.occluders.size(), 0);
  std::uniform_real_distribution<double> at(0, 10), depth(0.5, 5.5), step(-1.5, 1.5);
  std::size_t checked = 0, skipped_behind = 0;
  for (std::uint32_t q = 1; q <= 2000; ++q) {
    const Point2 a{at(rng), at(rng)};
    const Point2 b{std::clamp(a.x + step(rng), 0.0, 10.0), std::clamp(a.y + step(rng), 0.0, 10.0)};
    const double max_depth = depth(rng);
    const std::vector<std::uint32_t> ids = met(grid, a, b, max_depth, stamp, q);
    std::vector<int> seen(setup.occluders.size(), 0);
    for (std::uint32_t id : ids) {
      ASSERT_EQ(seen[id]++, 0) << "occluder " << id << " met twice";
      EXPECT_LT(setup.occluders[id].min_depth, max_depth * (1 + 1e-6)) << "occluder " << id << " lies behind";
    }
    for (std::uint32_t i = 0; i < setup.occluders.size(); ++i) {
      if (!meets(&setup.polygon_points[setup.occluders[i].first_point], a, b)) continue;
      if (setup.occluders[i].min_depth >= max_depth) {
        ++skipped_behind;
        continue;
      }
      ++checked;
      EXPECT_EQ(seen[i], 1) << "occluder " << i << " crossed at depth " << setup.occluders[i].min_depth
                            << " < " << max_depth << " but not met";
    }
  }
  EXPECT_GT(checked, 2000u);  // the test met many occluders it had to, and many it had to pass over
  EXPECT_GT(skipped_behind, 2000u);
}

// An occluder a hair nearer than the edge's farthest point (one double's step, below a float's) is met;
// one a millionth farther than it is not. Depths are rounded to floats inside the grid: downwards, or the
// first would be passed over half the time.
TEST(FaceGrid, DepthsOneStepApartAreTold) {
  std::mt19937_64 rng(7);
  const FrameSetup setup = random_triangles(rng, 600);
  const FaceGrid grid(setup, Rect2{0, 0, 10, 10}, 1);
  std::vector<std::uint32_t> stamp(setup.occluders.size(), 0);
  std::uint32_t mark = 0;
  for (std::uint32_t i = 0; i < setup.occluders.size(); ++i) {
    const Occluder& o = setup.occluders[i];
    const Point2* t = &setup.polygon_points[o.first_point];
    const Point2 mid{(t[0].x + t[1].x + t[2].x) / 3, (t[0].y + t[1].y + t[2].y) / 3};
    const Point2 a{mid.x - 1e-3, mid.y}, b{mid.x + 1e-3, mid.y};
    auto has = [&](double max_depth) {
      for (std::uint32_t id : met(grid, a, b, max_depth, stamp, ++mark))
        if (id == i) return true;
      return false;
    };
    EXPECT_TRUE(has(std::nextafter(o.min_depth, 10.0))) << "occluder " << i << " at " << o.min_depth;
    EXPECT_FALSE(has(o.min_depth * (1 - 1e-6))) << "occluder " << i;
  }
}

// The grid, and so the order occluders are met in, is the same whatever the number of threads.
TEST(FaceGrid, SameForAnyNumberOfThreads) {
  std::mt19937_64 rng(11);
  const FrameSetup setup = random_triangles(rng, 20000);
  const Rect2 domain{0, 0, 10, 10};
  const FaceGrid one(setup, domain, 1), two(setup, domain, 2);
  std::vector<std::uint32_t> stamp1(setup.occluders.size(), 0), stamp2(setup.occluders.size(), 0);
  std::uniform_real_distribution<double> at(0, 10), depth(0.5, 5.5);
  for (std::uint32_t q = 1; q <= 300; ++q) {
    const Point2 a{at(rng), at(rng)}, b{at(rng), at(rng)};
    const double max_depth = depth(rng);
    EXPECT_EQ(met(one, a, b, max_depth, stamp1, q), met(two, a, b, max_depth, stamp2, q));
  }
}

}  // namespace
}  // namespace hlr
