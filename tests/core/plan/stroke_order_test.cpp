// Stroke ordering on synthetic strokes: greedy, circuit, exact and improved orders are permutations of the
// strokes (each possibly reversed, closed ones rotated), improvement never lengthens the tour, the exact
// order is optimal (brute force), improvement with shared neighbour lists works, and the k-d tree and grid
// neighbour queries agree with a linear scan.
#include "core/plan/stroke_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <vector>

#include "core/plan/kd_tree.hpp"
#include "tests/core/plan/plan_test_util.hpp"

namespace hlr::plan {
namespace {

using plan_test::Rng;

// Random strokes over `vertices`: open polylines and a few closed loops.
std::vector<GridStroke> random_strokes(Rng& r, std::vector<GridPoint>& vertices, int n, int size) {
  std::vector<GridStroke> strokes;
  for (int s = 0; s < n; ++s) {
    GridStroke g;
    g.closed = r.integer(0, 4) == 0;
    const int len = r.integer(g.closed ? 3 : 1, 5);
    for (int k = 0; k < len + (g.closed ? 0 : 1); ++k) {
      g.vertices.push_back(static_cast<std::uint32_t>(vertices.size()));
      vertices.push_back({r.integer(0, size), r.integer(0, size)});
    }
    if (g.closed) g.vertices.push_back(g.vertices.front());
    g.circuit = static_cast<std::uint32_t>(s / 3);  // circuits of three
    strokes.push_back(std::move(g));
  }
  return strokes;
}

// A canonical form of a stroke that ignores direction and (for closed strokes) the starting vertex.
std::vector<std::uint32_t> canonical(const GridStroke& s) {
  std::vector<std::uint32_t> v = s.vertices;
  if (s.closed) {
    v.pop_back();
    std::vector<std::uint32_t> best;
    for (int dir = 0; dir < 2; ++dir) {
      for (std::size_t k = 0; k < v.size(); ++k) {
        std::vector<std::uint32_t> c(v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
        c.insert(c.end(), v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k));
        if (best.empty() || c < best) best = c;
      }
      std::reverse(v.begin(), v.end());
    }
    return best;
  }
  std::vector<std::uint32_t> w(v.rbegin(), v.rend());
  return std::min(v, w);
}

std::multiset<std::vector<std::uint32_t>> canonical_set(const std::vector<GridStroke>& strokes) {
  std::multiset<std::vector<std::uint32_t>> out;
  for (const GridStroke& s : strokes) out.insert(canonical(s));
  return out;
}

TEST(StrokeOrder, OrdersArePermutationsAndImprovementHelps) {
  Rng r(99);
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<GridPoint> vertices;
    const int n = r.integer(1, trial < 40 ? 40 : 3000);
    const std::vector<GridStroke> strokes = random_strokes(r, vertices, n, 1000);
    const TourEnds ends{
        {static_cast<double>(r.integer(-100, 1100)), static_cast<double>(r.integer(-100, 1100))},
        {static_cast<double>(r.integer(-100, 1100)), static_cast<double>(r.integer(-100, 1100))},
        r.integer(0, 1) == 1};
    const auto want = canonical_set(strokes);
    std::vector<GridStroke> greedy = strokes, circuits = strokes;
    order_greedy(greedy, vertices, ends);
    order_circuits(circuits, vertices, ends);
    EXPECT_EQ(canonical_set(greedy), want);
    EXPECT_EQ(canonical_set(circuits), want);
    for (const std::vector<GridStroke>* seed : {&greedy, &circuits}) {
      std::vector<GridStroke> improved = *seed;
      const double before = tour_travel(improved, vertices, ends);
      const ImproveResult res = improve_order(improved, vertices, ends);
      EXPECT_EQ(canonical_set(improved), want);
      const double after = tour_travel(improved, vertices, ends);
      EXPECT_LE(after, before + 1e-6) << "trial " << trial;
      EXPECT_LE(res.work, 500 * (strokes.size() + 1) + 25000);  // the cap, and at most one move past it
      if (n <= static_cast<int>(kExactOrderStrokes)) {
        std::vector<GridStroke> exact = strokes;
        if (order_exact(exact, vertices, ends)) {
          EXPECT_EQ(canonical_set(exact), want);
          EXPECT_LE(tour_travel(exact, vertices, ends), after + 1e-6);
        }
      }
    }
  }
}

// order_exact against enumeration of every order, direction and entry vertex.
// Beyond 16 384 strokes improve_order() can take the matching's neighbour lists over the stroke ends
// (pen_plan.cpp): the result is still a permutation, no longer, and deterministic.
TEST(StrokeOrder, ImproveWithSharedNeighbours) {
  Rng r(5);
  std::vector<GridPoint> vertices;
  std::vector<GridStroke> strokes;
  for (std::uint32_t s = 0; s < 17000; ++s) {
    GridStroke g;
    for (int k = 0; k < 2; ++k) {
      g.vertices.push_back(static_cast<std::uint32_t>(vertices.size()));
      vertices.push_back({r.integer(0, 20000), r.integer(0, 20000)});
    }
    strokes.push_back(std::move(g));
  }
  std::vector<std::uint32_t> listed(vertices.size());
  std::iota(listed.begin(), listed.end(), 0u);
  std::vector<Pt> points;
  for (const GridPoint& v : vertices) points.push_back({static_cast<double>(v.x), static_cast<double>(v.y)});
  std::vector<std::uint32_t> lists;
  all_k_nearest(points, 6, lists, false);
  const SharedNeighbours shared{&listed, &lists, 6};
  const TourEnds ends{{0, 0}, {100, 0}, false};
  std::vector<GridStroke> a = strokes, b = strokes;
  order_circuits(a, vertices, ends);
  const double before = tour_travel(a, vertices, ends);
  b = a;
  const ImproveResult ra = improve_order(a, vertices, ends, 500, &shared);
  improve_order(b, vertices, ends, 500, &shared);
  EXPECT_EQ(canonical_set(a), canonical_set(strokes));
  EXPECT_LT(tour_travel(a, vertices, ends), before);
  EXPECT_GT(ra.moves, 0u);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].vertices, b[i].vertices);
}

TEST(StrokeOrder, ExactIsOptimal) {
  Rng r(5);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<GridPoint> vertices;
    std::vector<GridStroke> strokes = random_strokes(r, vertices, r.integer(1, 5), 50);
    const TourEnds ends{{0, 0}, {50, 50}, trial % 3 == 0};
    std::vector<GridStroke> exact = strokes;
    ASSERT_TRUE(order_exact(exact, vertices, ends));
    // Enumerate.
    std::vector<int> order(strokes.size());
    std::iota(order.begin(), order.end(), 0);
    double best = 1e300;
    auto pt = [&](std::uint32_t v) {
      return Pt{static_cast<double>(vertices[v].x), static_cast<double>(vertices[v].y)};
    };
    do {
      // Choices per stroke: (entry, exit) vertex pairs.
      std::vector<std::vector<std::pair<Pt, Pt>>> ch;
      for (int s : order) {
        const GridStroke& g = strokes[static_cast<std::size_t>(s)];
        std::vector<std::pair<Pt, Pt>> c;
        if (g.closed) {
          for (std::size_t k = 0; k + 1 < g.vertices.size(); ++k)
            c.emplace_back(pt(g.vertices[k]), pt(g.vertices[k]));
        } else {
          c.emplace_back(pt(g.vertices.front()), pt(g.vertices.back()));
          c.emplace_back(pt(g.vertices.back()), pt(g.vertices.front()));
        }
        ch.push_back(c);
      }
      std::vector<std::size_t> pick(ch.size(), 0);
      for (;;) {
        double t = 0;
        Pt here = ends.start;
        for (std::size_t i = 0; i < ch.size(); ++i) {
          t += std::sqrt(dist2(here, ch[i][pick[i]].first));
          here = ch[i][pick[i]].second;
        }
        if (!ends.end_free) t += std::sqrt(dist2(here, ends.end));
        best = std::min(best, t);
        std::size_t i = 0;
        while (i < ch.size() && ++pick[i] == ch[i].size()) pick[i++] = 0;
        if (i == ch.size()) break;
      }
    } while (std::next_permutation(order.begin(), order.end()));
    EXPECT_NEAR(tour_travel(exact, vertices, ends), best, 1e-9) << "trial " << trial;
  }
}

// The neighbour lists are the same whether the queries run in parts side by side or on one thread
// (40 000 points: several parts), exact and approximate.
TEST(KdTree, AllKNearestSameOnAnyNumberOfThreads) {
  Rng r(23);
  std::vector<Pt> p;
  for (int i = 0; i < 40000; ++i)
    p.push_back({static_cast<double>(r.integer(0, 3000)), static_cast<double>(r.integer(0, 2000))});
  for (const bool exact : {true, false}) {
    std::vector<std::uint32_t> one, parts;
    all_k_nearest(p, 8, one, exact, 1);
    all_k_nearest(p, 8, parts, exact, 0);
    EXPECT_EQ(one, parts) << (exact ? "exact" : "approximate");
  }
}

TEST(KdTree, NearestAndKNearestMatchLinearScan) {
  Rng r(17);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = r.integer(1, 2000);
    std::vector<Pt> p;
    for (int i = 0; i < n; ++i)
      p.push_back({static_cast<double>(r.integer(0, trial % 2 ? 30 : 100000)),
                   static_cast<double>(r.integer(0, 100))});
    KdTree tree(p);
    std::vector<char> alive(static_cast<std::size_t>(n), 1);
    std::vector<std::uint32_t> found, grid;
    all_k_nearest(p, 5, grid);
    for (int q = 0; q < 300; ++q) {
      const Pt at{r(-10, 100010), r(-10, 110)};
      // Linear scan: (distance², index) order over the live points.
      std::vector<std::pair<double, std::uint32_t>> all;
      for (std::uint32_t i = 0; i < p.size(); ++i)
        if (alive[i]) all.emplace_back(dist2(at, p[i]), i);
      std::sort(all.begin(), all.end());
      const std::uint32_t nn = tree.nearest(at);
      // The bottom-up search from any point's leaf (live, erased or out of range) gives the same answer.
      EXPECT_EQ(tree.nearest(at, static_cast<std::uint32_t>(r.integer(0, n))), nn);
      if (all.empty()) {
        EXPECT_EQ(nn, KdTree::kNone);
      } else {
        EXPECT_EQ(nn, all[0].second);
      }
      tree.k_nearest(at, 4, KdTree::kNone, found);
      ASSERT_EQ(found.size(), std::min<std::size_t>(4, all.size()));
      for (std::size_t k = 0; k < found.size(); ++k) EXPECT_EQ(found[k], all[k].second);
      if (q % 3 == 0 && nn != KdTree::kNone) {
        tree.erase(nn);
        alive[nn] = 0;
      }
    }
    EXPECT_EQ(tree.alive(), static_cast<std::size_t>(std::count(alive.begin(), alive.end(), 1)));
    // The grid's all-points k-nearest equals the tree's on the full set; the approximate one lists
    // min(5, n − 1) distinct other points, nearest first.
    KdTree full(p);
    std::vector<std::uint32_t> approx;
    all_k_nearest(p, 5, approx, false);
    for (std::uint32_t i = 0; i < p.size(); ++i) {
      full.k_nearest(p[i], 5, i, found);
      for (std::size_t k = 0; k < 5; ++k)
        EXPECT_EQ(grid[i * 5 + k], k < found.size() ? found[k] : KdTree::kNone);
      std::set<std::uint32_t> seen;
      double last = 0;
      for (std::size_t k = 0; k < 5; ++k) {
        const std::uint32_t j = approx[i * 5 + k];
        if (k >= found.size()) {
          EXPECT_EQ(j, KdTree::kNone);
          continue;
        }
        ASSERT_NE(j, KdTree::kNone);
        EXPECT_NE(j, i);
        EXPECT_TRUE(seen.insert(j).second);
        EXPECT_GE(dist2(p[i], p[j]), last);
        last = dist2(p[i], p[j]);
      }
    }
  }
}

}  // namespace
}  // namespace hlr::plan
