#include "core/plan/euler_strokes.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>

namespace hlr::plan {

std::vector<VertexPair> sequential_pairing(const PenGraph& g) {
  constexpr std::uint32_t kNone = ~0u;
  std::vector<std::uint32_t> waiting(g.components, kNone);  // per component: an unpaired odd vertex
  std::vector<VertexPair> pairs;
  pairs.reserve(g.odd.size() / 2);
  for (std::uint32_t v : g.odd) {
    std::uint32_t& w = waiting[g.component[v]];
    if (w == kNone) {
      w = v;
    } else {
      pairs.emplace_back(w, v);
      w = kNone;
    }
  }
  return pairs;
}

std::vector<GridStroke> euler_strokes(const PenGraph& g, const std::vector<VertexPair>& pairs) {
  const std::size_t nv = g.vertices.size(), ne = g.edges.size(), nt = ne + pairs.size();
  auto endpoints = [&](std::size_t e) -> VertexPair {
    return e < ne ? VertexPair{g.edges[e].u, g.edges[e].v} : pairs[e - ne];
  };
  // Adjacency of the augmented multigraph, in edge order (deterministic).
  std::vector<std::uint32_t> offset(nv + 1, 0);
  for (std::size_t e = 0; e < nt; ++e) {
    const auto [a, b] = endpoints(e);
    if (a == b || a >= nv || b >= nv) throw std::invalid_argument("euler_strokes: bad vertex pair");
    ++offset[a + 1], ++offset[b + 1];
  }
  for (std::size_t v = 0; v < nv; ++v) {
    if ((offset[v + 1] % 2) != 0) throw std::invalid_argument("euler_strokes: pairing leaves an odd vertex");
    offset[v + 1] += offset[v];
  }
  std::vector<std::uint32_t> adjacent(offset[nv]);
  {
    std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
    for (std::size_t e = 0; e < nt; ++e) {
      const auto [a, b] = endpoints(e);
      adjacent[fill[a]++] = static_cast<std::uint32_t>(e);
      adjacent[fill[b]++] = static_cast<std::uint32_t>(e);
    }
  }

  std::vector<GridStroke> strokes;
  strokes.reserve(pairs.size() + g.components);
  std::vector<char> used(nt, 0);
  std::vector<std::uint32_t> next(offset.begin(), offset.end() - 1);
  constexpr std::uint32_t kNone = ~0u;
  struct Step {
    std::uint32_t vertex, edge;  // the vertex reached and the edge it was reached by
  };
  std::vector<Step> stack, circuit;
  for (std::uint32_t start = 0; start < nv; ++start) {
    // Hierholzer: walk until stuck, then back up, emitting the circuit in reverse.
    stack.assign(1, {start, kNone});
    circuit.clear();
    while (!stack.empty()) {
      const std::uint32_t v = stack.back().vertex;
      std::uint32_t& i = next[v];
      while (i < offset[v + 1] && used[adjacent[i]]) ++i;
      if (i == offset[v + 1]) {
        circuit.push_back(stack.back());
        stack.pop_back();
      } else {
        const std::uint32_t e = adjacent[i++];
        used[e] = 1;
        const auto [a, b] = endpoints(e);
        stack.push_back({a == v ? b : a, e});
      }
    }
    if (circuit.size() < 2) continue;  // no edge left at `start`
    const std::uint32_t circuit_id = strokes.empty() ? 0 : strokes.back().circuit + 1;
    // circuit reversed: vertex k reached from vertex k−1 by edge k.
    const std::size_t m = circuit.size() - 1;  // edges
    auto vertex_at = [&](std::size_t k) { return circuit[m - k].vertex; };
    auto edge_at = [&](std::size_t k) { return circuit[m - k].edge; };  // k ≥ 1
    std::size_t first_virtual = 0;
    for (std::size_t k = 1; k <= m && !first_virtual; ++k)
      if (edge_at(k) >= ne) first_virtual = k;
    if (!first_virtual) {
      GridStroke s;
      s.closed = true;
      s.circuit = circuit_id;
      s.vertices.reserve(m + 1);
      for (std::size_t k = 0; k <= m; ++k) s.vertices.push_back(vertex_at(k));
      strokes.push_back(std::move(s));
      continue;
    }
    // Cut at the virtual edges: each stroke runs from the vertex a virtual edge reaches to the vertex before
    // the next virtual edge (edge indices 1..m, wrapping around), sized before it is filled.
    std::size_t kv = first_virtual;
    do {
      std::size_t k = kv, len = 1;
      for (;;) {
        k = k == m ? 1 : k + 1;
        if (edge_at(k) >= ne) break;
        ++len;
      }
      assert(len >= 2);
      GridStroke s;
      s.circuit = circuit_id;
      s.vertices.resize(len);
      for (std::size_t t = 0, q = kv; t < len; ++t, q = q == m ? 1 : q + 1) s.vertices[t] = vertex_at(q);
      strokes.push_back(std::move(s));
      kv = k;
    } while (kv != first_virtual);
  }
  return strokes;
}

void rotate_closed(GridStroke& s, std::size_t k) {
  if (k == 0) return;
  std::vector<std::uint32_t>& v = s.vertices;
  v.pop_back();
  std::rotate(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  v.push_back(v.front());
}

}  // namespace hlr::plan
