// The drawing graph: snapping, duplicate and overlap merging, T-junctions, degrees and components; the
// Euler strokes and the odd-vertex matching built on it.
#include "core/plan/pen_graph.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/plan/euler_strokes.hpp"
#include "core/plan/odd_matching.hpp"
#include "tests/core/plan/plan_test_util.hpp"

namespace hlr::plan {
namespace {

using plan_test::Unit;

GridSegment seg(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by) { return {{ax, ay}, {bx, by}}; }

std::vector<Unit> graph_units(const PenGraph& g) {
  std::vector<Unit> u;
  for (const GraphEdge& e : g.edges) plan_test::append_units(g.vertices[e.u], g.vertices[e.v], u);
  std::sort(u.begin(), u.end());
  return u;
}

std::vector<Unit> stroke_units(const PenGraph& g, const std::vector<GridStroke>& strokes) {
  std::vector<Unit> u;
  for (const GridStroke& s : strokes)
    for (std::size_t k = 1; k < s.vertices.size(); ++k)
      plan_test::append_units(g.vertices[s.vertices[k - 1]], g.vertices[s.vertices[k]], u);
  std::sort(u.begin(), u.end());
  return u;
}

TEST(PenGraph, DuplicatesReversedAndOverlapsMerge) {
  const std::vector<GridSegment> s{seg(0, 0, 10, 0), seg(10, 0, 0, 0), seg(5, 0, 15, 0), seg(2, 0, 3, 0),
                                   seg(0, 0, 10, 0)};
  const PenGraph g = build_pen_graph(s, 0);
  // Union [0, 15], split at 2, 3, 5, 10: five edges on one line.
  EXPECT_EQ(g.edges.size(), 5u);
  EXPECT_EQ(g.components, 1u);
  EXPECT_EQ(g.odd.size(), 2u);
  EXPECT_EQ(g.lift_lower_bound, 1u);
  std::vector<Unit> expected;
  plan_test::append_units({0, 0}, {15, 0}, expected);
  EXPECT_EQ(graph_units(g), expected);
}

TEST(PenGraph, DiagonalOverlapOnTheLattice) {
  // Collinear on the line y = x/2 (primitive step (2, 1)); (3, 1.5) is not a lattice point of it.
  const PenGraph g = build_pen_graph(std::vector<GridSegment>{seg(0, 0, 8, 4), seg(4, 2, 12, 6)}, 0);
  EXPECT_EQ(g.edges.size(), 3u);  // [0,4], [4,8], [8,12] in x
  EXPECT_EQ(g.lift_lower_bound, 1u);
}

TEST(PenGraph, TJunctionConnects) {
  // A piece ending on another (the hidden-line engine's T-junction).
  const PenGraph g = build_pen_graph(std::vector<GridSegment>{seg(0, 0, 10, 0), seg(4, 0, 4, 7)}, 0);
  EXPECT_EQ(g.components, 1u);
  EXPECT_EQ(g.edges.size(), 3u);
  EXPECT_EQ(g.odd.size(), 4u);  // 0, 10, 7 ends and the junction (degree 3)
  EXPECT_EQ(g.lift_lower_bound, 2u);
}

TEST(PenGraph, CrossingPiecesStayApart) {
  const PenGraph g = build_pen_graph(std::vector<GridSegment>{seg(0, 0, 10, 10), seg(0, 10, 10, 0)}, 0);
  EXPECT_EQ(g.components, 2u);
  EXPECT_EQ(g.edges.size(), 2u);
  EXPECT_EQ(g.lift_lower_bound, 2u);
}

TEST(PenGraph, ToleranceJoinsNearTJunctionAndNearDuplicates) {
  // The stem ends one unit off the bar: exact mode leaves it apart, tolerance 1 joins it.
  const std::vector<GridSegment> t{seg(0, 0, 100, 0), seg(40, 1, 40, 30)};
  EXPECT_EQ(build_pen_graph(t, 0).components, 2u);
  const PenGraph joined = build_pen_graph(t, 1);
  EXPECT_EQ(joined.components, 1u);
  EXPECT_EQ(joined.edges.size(), 3u);
  // Two copies of a long line whose ends snapped to neighbouring grid points: one drawing, plus the
  // unit-long stubs at the ends.
  const PenGraph d = build_pen_graph(std::vector<GridSegment>{seg(0, 0, 1000, 301), seg(1, 0, 1000, 300)}, 1);
  EXPECT_EQ(d.components, 1u);
  EXPECT_LE(d.edges.size(), 4u);
  double length = 0;
  for (const GraphEdge& e : d.edges)
    length += std::hypot(static_cast<double>(d.vertices[e.v].x - d.vertices[e.u].x),
                         static_cast<double>(d.vertices[e.v].y - d.vertices[e.u].y));
  EXPECT_LT(length, std::hypot(1000.0, 301.0) + 3);
}

// The tolerance is for loose ends only: a vertex one unit off a piece where two pieces meet (a thin sliver
// of a tessellated outline) is not joined — that would change vertex parities for no visible gain.
TEST(PenGraph, ToleranceLeavesContinuedVerticesAlone) {
  const std::vector<GridSegment> s{seg(0, 0, 500, 0), seg(500, 0, 1000, 0), seg(0, 1, 250, 1), seg(250, 1, 1000, 1)};
  const PenGraph g = build_pen_graph(s, 1.5);
  EXPECT_EQ(g.components, 2u);
  EXPECT_EQ(g.edges.size(), 4u);
  EXPECT_EQ(g.lift_lower_bound, 2u);
}

TEST(PenGraph, DegenerateAndOutOfRangeDropped) {
  const PenGraph g =
      build_pen_graph(std::vector<GridSegment>{seg(3, 3, 3, 3), seg(0, 0, kMaxGridCoordinate + 1, 0), seg(0, 0, 1, 0)}, 1);
  EXPECT_EQ(g.edges.size(), 1u);
  EXPECT_EQ(g.vertices.size(), 2u);
}

// The thesis's six-point drawing (Diagram 1.1): hexagon 1…6 with chords 1-3 and 4-6; odd points 1, 3, 4,
// 6; 6 candidate pen-up lines, 3 pairings, the best pairs neighbours (1-6, 3-4).
// The graph is the same whether its pieces are split in parts side by side or on one thread: 30 000
// short pieces on a small lattice (many overlaps, T-junctions and loose ends near other pieces).
TEST(PenGraph, SameGraphOnAnyNumberOfThreads) {
  plan_test::Rng r(31);
  std::vector<GridSegment> segments;
  for (int i = 0; i < 30000; ++i) {
    const GridPoint a{r.integer(0, 400), r.integer(0, 400)};
    const GridPoint b{a.x + r.integer(-12, 12), a.y + r.integer(-12, 12)};
    segments.push_back({a, b});
  }
  const PenGraph one = build_pen_graph(segments, 1.5, 1), parts = build_pen_graph(segments, 1.5, 0);
  ASSERT_EQ(one.vertices.size(), parts.vertices.size());
  for (std::size_t v = 0; v < one.vertices.size(); ++v) EXPECT_TRUE(one.vertices[v] == parts.vertices[v]);
  ASSERT_EQ(one.edges.size(), parts.edges.size());
  for (std::size_t e = 0; e < one.edges.size(); ++e) {
    EXPECT_EQ(one.edges[e].u, parts.edges[e].u);
    EXPECT_EQ(one.edges[e].v, parts.edges[e].v);
  }
  EXPECT_EQ(one.odd, parts.odd);
  EXPECT_EQ(one.lift_lower_bound, parts.lift_lower_bound);
}

TEST(PenGraph, ThesisSixPointDrawing) {
  std::vector<GridPoint> p(7);
  for (int i = 1; i <= 6; ++i) {
    const double a = (i - 1) * std::numbers::pi / 3;
    p[i] = {std::llround(1000 * std::cos(a)), std::llround(1000 * std::sin(a))};
  }
  std::vector<GridSegment> s;
  for (auto [a, b] : {std::pair{1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 1}, {1, 3}, {4, 6}}) s.push_back({p[a], p[b]});
  const PenGraph g = build_pen_graph(s, 0);
  ASSERT_EQ(g.vertices.size(), 6u);
  EXPECT_EQ(g.edges.size(), 8u);
  std::vector<GridPoint> odd;
  for (std::uint32_t v : g.odd) odd.push_back(g.vertices[v]);
  EXPECT_EQ(odd, (std::vector<GridPoint>{p[1], p[3], p[4], p[6]}));
  EXPECT_EQ(g.lift_lower_bound, 2u);
  std::vector<Pt> pts;
  for (GridPoint q : odd) pts.push_back({static_cast<double>(q.x), static_cast<double>(q.y)});
  const auto m = min_weight_matching(pts);
  ASSERT_EQ(m.size(), 2u);
  auto has = [&](std::uint32_t a, std::uint32_t b) {
    return std::any_of(m.begin(), m.end(), [&](auto e) { return (e.first == a && e.second == b) || (e.first == b && e.second == a); });
  };
  EXPECT_TRUE(has(0, 3));  // 1-6
  EXPECT_TRUE(has(1, 2));  // 3-4
  EXPECT_NEAR(exact_matching_weight(pts), 2000, 1);
  // Strokes: two, together drawing the eight edges once.
  for (const auto& pairs : {sequential_pairing(g), std::vector<VertexPair>{{g.odd[0], g.odd[3]}, {g.odd[1], g.odd[2]}}}) {
    const auto strokes = euler_strokes(g, pairs);
    EXPECT_EQ(strokes.size(), 2u);
    EXPECT_EQ(stroke_units(g, strokes), graph_units(g));
  }
}

// Perfect matchings of 2k points: (2k − 1)!! of them — 3 for 4 points, 105 for the cube's 8. The dynamic
// programme equals enumeration of all of them.
double enumerate_matchings(std::vector<Pt>& p, std::vector<int>& left, std::size_t& count) {
  if (left.empty()) {
    ++count;
    return 0;
  }
  const int a = left.back();
  left.pop_back();
  double best = 1e300;
  for (std::size_t i = 0; i < left.size(); ++i) {
    const int b = left[i];
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
    best = std::min(best, std::sqrt(dist2(p[a], p[b])) + enumerate_matchings(p, left, count));
    left.insert(left.begin() + static_cast<std::ptrdiff_t>(i), b);
  }
  left.push_back(a);
  return best;
}

TEST(OddMatching, ExactAgreesWithEnumeration) {
  plan_test::Rng r(7);
  for (int n : {2, 4, 6, 8, 10}) {
    for (int trial = 0; trial < 5; ++trial) {
      std::vector<Pt> p;
      for (int i = 0; i < n; ++i) p.push_back({r(0, 100), r(0, 100)});
      std::vector<int> left(n);
      std::iota(left.begin(), left.end(), 0);
      std::size_t count = 0;
      const double best = enumerate_matchings(p, left, count);
      const std::size_t pairings[] = {1, 1, 3, 15, 105, 945};
      EXPECT_EQ(count, pairings[n / 2]);
      EXPECT_NEAR(exact_matching_weight(p), best, 1e-9);
      double w = 0;
      for (auto [a, b] : min_weight_matching(p)) w += std::sqrt(dist2(p[a], p[b]));
      EXPECT_NEAR(w, best, 1e-9);
    }
  }
}

// Large sets: the heuristic is a perfect matching, no worse than pairing in index order, and close to the
// exact optimum where that can still be computed (20 points).
TEST(OddMatching, HeuristicIsPerfectAndGood) {
  plan_test::Rng r(11);
  for (int n : {18, 20, 200, 5000}) {
    std::vector<Pt> p;
    for (int i = 0; i < n; ++i) p.push_back({r(0, 1000), r(0, 1000)});
    const auto m = min_weight_matching(p);
    ASSERT_EQ(m.size(), static_cast<std::size_t>(n / 2));
    std::vector<int> seen(n, 0);
    double w = 0, naive = 0;
    for (auto [a, b] : m) ++seen[a], ++seen[b], w += std::sqrt(dist2(p[a], p[b]));
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
    for (int i = 0; i < n; i += 2) naive += std::sqrt(dist2(p[i], p[i + 1]));
    EXPECT_LT(w, naive);
    if (n <= 20) {
      EXPECT_LE(w, 1.25 * exact_matching_weight(p)) << n;
    }
  }
}

// Euler strokes on random graphs: max(1, odd/2) strokes per component, every edge once, iterative on a
// component of 2·10^5 edges (a long zig-zag band).
TEST(EulerStrokes, FewestStrokesEveryEdgeOnce) {
  plan_test::Rng r(3);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<GridSegment> s;
    const int n = r.integer(1, 60);
    for (int i = 0; i < n; ++i) s.push_back(seg(r.integer(0, 8), r.integer(0, 8), r.integer(0, 8), r.integer(0, 8)));
    const PenGraph g = build_pen_graph(s, 0);
    const auto strokes = euler_strokes(g, sequential_pairing(g));
    EXPECT_EQ(strokes.size(), g.lift_lower_bound);
    EXPECT_EQ(stroke_units(g, strokes), graph_units(g));
    for (const GridStroke& st : strokes) {
      EXPECT_GE(st.vertices.size(), 2u);
      if (st.closed) {
        EXPECT_EQ(st.vertices.front(), st.vertices.back());
      }
    }
  }
  std::vector<GridSegment> band;
  for (std::int64_t i = 0; i < 100000; ++i) {
    band.push_back(seg(i, 0, i + 1, 0));
    band.push_back(seg(i, 0, i + 1, 1));
  }
  const PenGraph g = build_pen_graph(band, 0);
  const auto strokes = euler_strokes(g, sequential_pairing(g));
  EXPECT_EQ(strokes.size(), g.lift_lower_bound);
  std::size_t edges = 0;
  for (const GridStroke& st : strokes) edges += st.vertices.size() - 1;
  EXPECT_EQ(edges, g.edges.size());
  // One closed square of 2·10^5 unit pieces: a single closed stroke.
  std::vector<GridSegment> square;
  for (std::int64_t i = 0; i < 50000; ++i) {
    square.push_back(seg(i, 0, i + 1, 0));
    square.push_back(seg(50000, i, 50000, i + 1));
    square.push_back(seg(i + 1, 50000, i, 50000));
    square.push_back(seg(0, i + 1, 0, i));
  }
  const PenGraph sq = build_pen_graph(square, 0);
  const auto loop = euler_strokes(sq, sequential_pairing(sq));
  ASSERT_EQ(loop.size(), 1u);
  EXPECT_TRUE(loop[0].closed);
  EXPECT_EQ(loop[0].vertices.size(), 200001u);
}

}  // namespace
}  // namespace hlr::plan
