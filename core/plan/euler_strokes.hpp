// Drawing each connected component with the fewest strokes: pair the odd-degree vertices with virtual
// edges, walk an Euler circuit of the augmented graph (Hierholzer, iterative), and cut it at the virtual
// edges. A component with k > 0 odd vertices gives k/2 open strokes, an even one a single closed stroke.
// Virtual edges may join odd vertices of different components: each augmented circuit still cuts into one
// stroke per virtual edge, every stroke inside one component, so the count stays Σ max(1, k/2).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/plan/pen_graph.hpp"

namespace hlr::plan {

// A stroke as graph vertices; `closed` strokes start and end at the same vertex (front() == back()) and
// may be entered at any of their vertices.
struct GridStroke {
  std::vector<std::uint32_t> vertices;
  bool closed = false;
  // euler_strokes(): the augmented circuit it was cut from (strokes in circuit order).
  std::uint32_t circuit = 0;
};

using VertexPair = std::pair<std::uint32_t, std::uint32_t>;

// Every odd vertex of `g` must appear in exactly one pair, and no other vertex in any. Each edge of `g` is
// drawn exactly once. Strokes come out grouped by augmented circuit, in the circuit's order.
std::vector<GridStroke> euler_strokes(const PenGraph& g, const std::vector<VertexPair>& pairs);

// Closed stroke: start it at its `k`-th vertex (0 ≤ k < size − 1).
void rotate_closed(GridStroke& s, std::size_t k);

// The naive pairing: within each component, odd vertices taken in increasing number two by two.
std::vector<VertexPair> sequential_pairing(const PenGraph& g);

}  // namespace hlr::plan
