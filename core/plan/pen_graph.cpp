#include "core/plan/pen_graph.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>

#include "core/parallel.hpp"
#include "core/plan/key_sort.hpp"
#include "core/tolerance.hpp"

namespace hlr::plan {
namespace {

// floor(x / s) without a library call (|x / s| stays far below 2^63 here).
std::int64_t floor_div(double x, double s) {
  const double q = x / s;
  const auto i = static_cast<std::int64_t>(q);
  return i - (q < static_cast<double>(i) ? 1 : 0);
}

// A vertex lying on a segment: its parameter along the segment (dot product) and its number.
struct Split {
  std::int64_t t;
  std::uint32_t vertex;
};

}  // namespace

void compute_graph_structure(PenGraph& g) {
  const std::size_t nv = g.vertices.size();
  g.degree.assign(nv, 0);
  for (const GraphEdge& e : g.edges) ++g.degree[e.u], ++g.degree[e.v];

  // Union-find with path halving and union by size.
  std::vector<std::uint32_t> parent(nv), size(nv, 1);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const GraphEdge& e : g.edges) {
    std::uint32_t a = find(e.u), b = find(e.v);
    if (a == b) continue;
    if (size[a] < size[b]) std::swap(a, b);
    parent[b] = a;
    size[a] += size[b];
  }
  // Components numbered in order of their lowest vertex: deterministic.
  constexpr std::uint32_t kNone = ~0u;
  std::vector<std::uint32_t> label(nv, kNone);
  g.component.assign(nv, 0);
  g.components = 0;
  for (std::uint32_t v = 0; v < nv; ++v) {
    const std::uint32_t r = find(v);
    if (label[r] == kNone) label[r] = static_cast<std::uint32_t>(g.components++);
    g.component[v] = label[r];
  }
  g.odd.clear();
  g.component_odd.assign(g.components, 0);
  for (std::uint32_t v = 0; v < nv; ++v)
    if (g.degree[v] % 2) {
      g.odd.push_back(v);
      ++g.component_odd[g.component[v]];
    }
  g.lift_lower_bound = 0;
  for (std::uint32_t k : g.component_odd) g.lift_lower_bound += std::max<std::size_t>(1, k / 2);
}

PenGraph build_pen_graph(std::span<const GridSegment> segments, double tolerance, unsigned threads) {
  PenGraph g;
  tolerance = std::isfinite(tolerance) ? std::max(0.0, tolerance) : 0.0;

  // 1. Vertices: one per distinct snapped end point, numbered in order of first appearance. The end points
  //    are radix-sorted by packed coordinates (stable, so each run of equal points starts at its first
  //    occurrence), then numbered in a pass over the occurrences.
  std::vector<GridPoint> ends;  // a, b of every kept piece
  ends.reserve(2 * segments.size());
  for (const GridSegment& s : segments) {
    if (s.a == s.b) continue;
    if (std::max({std::llabs(s.a.x), std::llabs(s.a.y), std::llabs(s.b.x), std::llabs(s.b.y)}) >
        kMaxGridCoordinate)
      continue;
    ends.push_back(s.a), ends.push_back(s.b);
  }
  std::vector<GraphEdge> pieces(ends.size() / 2);  // (u, v) in piece order, unordered
  if (!ends.empty()) {
    std::int64_t x0 = ends[0].x, x1 = x0, y0 = ends[0].y, y1 = y0;
    for (const GridPoint& p : ends) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
      y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    const int ybits = static_cast<int>(std::bit_width(static_cast<std::uint64_t>(y1 - y0)));
    const int bits = ybits + static_cast<int>(std::bit_width(static_cast<std::uint64_t>(x1 - x0)));
    struct Keyed {
      std::uint64_t key;
      std::uint32_t occurrence;
    };
    std::vector<Keyed> keyed(ends.size());
    for (std::size_t i = 0; i < ends.size(); ++i)
      keyed[i] = {
          (static_cast<std::uint64_t>(ends[i].x - x0) << ybits) | static_cast<std::uint64_t>(ends[i].y - y0),
          static_cast<std::uint32_t>(i)};
    stable_sort_by_key_bits(
        keyed, [](const Keyed& k) { return k.key; }, 0, bits);
    constexpr std::uint32_t kUnset = ~0u;
    std::vector<std::uint32_t> first(ends.size()), id(ends.size(), kUnset);  // per occurrence
    for (std::size_t i = 0; i < keyed.size(); ++i)
      first[keyed[i].occurrence] =
          i > 0 && keyed[i].key == keyed[i - 1].key ? first[keyed[i - 1].occurrence] : keyed[i].occurrence;
    for (std::size_t i = 0; i < ends.size(); ++i) {
      if (first[i] == i) {
        id[i] = static_cast<std::uint32_t>(g.vertices.size());
        g.vertices.push_back(ends[i]);
      }
      (i % 2 ? pieces[i / 2].v : pieces[i / 2].u) = id[first[i]];
    }
  }
  const std::size_t nv = g.vertices.size();
  std::vector<std::uint32_t> raw_degree(nv, 0);  // pieces ending at each vertex
  for (const GraphEdge& p : pieces) ++raw_degree[p.u], ++raw_degree[p.v];
  if (pieces.empty()) {
    compute_graph_structure(g);
    return g;
  }

  // 2. A uniform grid of cells over the vertices, about two vertices per cell, as a dense array of cell
  //    ranges (CSR) with each cell's vertices and coordinates stored together.
  std::int64_t xmin = g.vertices[0].x, xmax = xmin, ymin = g.vertices[0].y, ymax = ymin;
  for (const GridPoint& p : g.vertices) {
    xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
    ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
  }
  const double width = static_cast<double>(xmax - xmin), height = static_cast<double>(ymax - ymin);
  double cell =
      std::max({2.0, 2 * tolerance + 1,
                std::sqrt(2 * std::max(width, 1.0) * std::max(height, 1.0) / static_cast<double>(nv))});
  std::int64_t cx0, cy0, nx, ny;
  for (;;) {
    cx0 = floor_div(static_cast<double>(xmin), cell) - 1,
    cy0 = floor_div(static_cast<double>(ymin), cell) - 1;
    nx = floor_div(static_cast<double>(xmax), cell) - cx0 + 2,
    ny = floor_div(static_cast<double>(ymax), cell) - cy0 + 2;
    if (static_cast<double>(nx) * static_cast<double>(ny) <= 4.0 * static_cast<double>(nv) + 4096) break;
    cell *= 1.5;
  }
  auto cell_of = [&](std::int64_t cx, std::int64_t cy) -> std::int64_t {
    cx -= cx0, cy -= cy0;
    return cx < 0 || cy < 0 || cx >= nx || cy >= ny ? -1 : cy * nx + cx;
  };
  std::vector<std::uint32_t> cell_start(static_cast<std::size_t>(nx * ny) + 1, 0);
  std::vector<std::uint32_t> vertex_cell(nv);
  for (std::uint32_t v = 0; v < nv; ++v) {
    vertex_cell[v] =
        static_cast<std::uint32_t>(cell_of(floor_div(static_cast<double>(g.vertices[v].x), cell),
                                           floor_div(static_cast<double>(g.vertices[v].y), cell)));
    ++cell_start[vertex_cell[v] + 1];
  }
  for (std::size_t c = 1; c < cell_start.size(); ++c) cell_start[c] += cell_start[c - 1];
  std::vector<std::uint32_t> cell_vertex(nv);
  std::vector<GridPoint> cell_point(nv);
  {
    std::vector<std::uint32_t> fill(cell_start.begin(), cell_start.end() - 1);
    for (std::uint32_t v = 0; v < nv; ++v) {
      const std::uint32_t at = fill[vertex_cell[v]]++;
      cell_vertex[at] = v;
      cell_point[at] = g.vertices[v];
    }
  }

  // 3. Split every piece at the vertices on it: parts of the pieces side by side, each with its own list
  //    of sub-pieces, read in piece order below.
  const double tol2 = tolerance * tolerance;
  const double reach = tolerance * std::sqrt(2.0) +
                       Tolerance::kPlanReachSlack;  // across the minor axis, per unit of major axis
  constexpr std::size_t kPartPieces = 4096;
  std::vector<std::vector<GraphEdge>> part_raw((pieces.size() + kPartPieces - 1) / kPartPieces);
  parallel_chunks(part_raw.size(), threads_for(pieces.size(), 2 * kPartPieces, threads), [&](std::size_t k) {
    std::vector<Split> splits;
    // Sub-pieces, u < v, possibly repeated; moved in once: the parts' lists share cache lines.
    std::vector<GraphEdge> raw;
    const std::size_t begin = k * kPartPieces, end = std::min(pieces.size(), begin + kPartPieces);
    raw.reserve((end - begin) + (end - begin) / 4);
    auto add_edge = [&](std::uint32_t a, std::uint32_t b) {
      if (a == b) return;
      raw.push_back({std::min(a, b), std::max(a, b)});
    };
    for (std::size_t pi = begin; pi < end; ++pi) {
      const GraphEdge& piece = pieces[pi];
      const GridPoint pa = g.vertices[piece.u], pb = g.vertices[piece.v];
      const std::int64_t dx = pb.x - pa.x, dy = pb.y - pa.y;
      const std::int64_t len2 = dx * dx + dy * dy;
      splits.clear();
      auto test_cell = [&](std::int64_t cx, std::int64_t cy) {
        const std::int64_t c = cell_of(cx, cy);
        if (c < 0) return;
        for (std::uint32_t i = cell_start[static_cast<std::size_t>(c)],
                           e = cell_start[static_cast<std::size_t>(c) + 1];
             i < e; ++i) {
          const GridPoint pw = cell_point[i];
          const std::int64_t wx = pw.x - pa.x, wy = pw.y - pa.y;
          const std::int64_t t = wx * dx + wy * dy;
          if (t <= 0 || t >= len2) continue;  // also skips the piece's own end points
          const std::int64_t cross = dx * wy - dy * wx;
          if (cross != 0) {
            const double cr = static_cast<double>(cross);
            if (cr * cr > tol2 * static_cast<double>(len2)) continue;
            if (raw_degree[cell_vertex[i]] != 1) continue;  // the tolerance is for loose ends only
          }
          splits.push_back({t, cell_vertex[i]});
        }
      };
      // Walk the cells within `tolerance` of the piece, one cell column (or row) of the major axis at a time.
      const bool x_major = std::llabs(dx) >= std::llabs(dy);
      const double a0 = static_cast<double>(x_major ? pa.x : pa.y),
                   a1 = static_cast<double>(x_major ? pb.x : pb.y);
      const double b0 = static_cast<double>(x_major ? pa.y : pa.x),
                   b1 = static_cast<double>(x_major ? pb.y : pb.x);
      const double lo = std::min(a0, a1), hi = std::max(a0, a1);
      const double slope = (b1 - b0) / (a1 - a0);  // |slope| ≤ 1; a1 ≠ a0 on the major axis
      const std::int64_t c_first = floor_div(lo - tolerance, cell), c_last = floor_div(hi + tolerance, cell);
      for (std::int64_t c = c_first; c <= c_last; ++c) {
        const double s0 = std::clamp(static_cast<double>(c) * cell, lo, hi);
        const double s1 = std::clamp(static_cast<double>(c + 1) * cell, lo, hi);
        const double m0 = b0 + slope * (s0 - a0), m1 = b0 + slope * (s1 - a0);
        const std::int64_t r_first = floor_div(std::min(m0, m1) - reach, cell);
        const std::int64_t r_last = floor_div(std::max(m0, m1) + reach, cell);
        for (std::int64_t r = r_first; r <= r_last; ++r) x_major ? test_cell(c, r) : test_cell(r, c);
      }
      if (splits.empty()) {
        add_edge(piece.u, piece.v);
        continue;
      }
      std::sort(splits.begin(), splits.end(),
                [](const Split& x, const Split& y) { return x.t != y.t ? x.t < y.t : x.vertex < y.vertex; });
      std::uint32_t prev = piece.u;
      for (const Split& sp : splits) {
        add_edge(prev, sp.vertex);
        prev = sp.vertex;
      }
      add_edge(prev, piece.v);
    }
    part_raw[k] = std::move(raw);
  });
  // 4. Deduplicate: bucket the sub-pieces by their lower vertex (counting sort, stable, read from the
  //    parts in order), drop repeats of the upper one within each bucket. Edges come out ordered by
  //    (u, first appearance).
  {
    std::vector<std::uint32_t> start(nv + 1, 0);
    for (const std::vector<GraphEdge>& raw : part_raw)
      for (const GraphEdge& e : raw) ++start[e.u + 1];
    for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> upper(start[nv]);
    {
      std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
      for (std::vector<GraphEdge>& raw : part_raw) {
        for (const GraphEdge& e : raw) upper[fill[e.u]++] = e.v;
        std::vector<GraphEdge>().swap(raw);
      }
    }
    std::vector<std::uint32_t> last_seen(nv, ~0u);  // last_seen[v] == u: edge (u, v) already taken
    g.edges.reserve(upper.size());
    for (std::uint32_t u = 0; u < nv; ++u)
      for (std::uint32_t i = start[u]; i < start[u + 1]; ++i) {
        const std::uint32_t v = upper[i];
        if (last_seen[v] == u) continue;
        last_seen[v] = u;
        g.edges.push_back({u, v});
      }
  }
  compute_graph_structure(g);
  return g;
}

}  // namespace hlr::plan
