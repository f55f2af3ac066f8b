// The drawing graph of one pen and layer: pieces snapped to the device grid, duplicates and overlapping
// collinear pieces merged, T-junctions joined, with degrees and connected components.
//
// Merging is done by one rule: every piece is split at each graph vertex that lies on it — strictly
// between its end points — and the resulting edges are deduplicated by their end points. This unions
// overlapping collinear pieces (each overlap holds an end point of one piece inside the other, so both
// split there and the shared part becomes one edge), removes exact duplicates, and connects T-junctions
// (a piece ending on another splits it). Pieces that merely cross are not joined.
//
// "Lies on" is exact (integer cross product 0) for every vertex, and within `tolerance` grid units for a
// loose end — a vertex where exactly one piece ends. Snapping moves each end point by up to √2/2 units,
// so a T-junction the hidden-line engine made exact can end up to √2 units off the snapped line it
// meets; a tolerance of 1.5 joins all of those, bending the piece it splits by at most that much.
// Limiting the tolerance to loose ends keeps near-parallel lines that are both continued elsewhere
// (the thin slivers near a tessellated sphere's outline) apart: merging them would save a little ink but
// break the parity of their vertices and cost many more pen lifts.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/plan/grid_point.hpp"

namespace hlr::plan {

// Snapped coordinates must stay within ±kMaxGridCoordinate so that products of differences fit 64 bits.
inline constexpr std::int64_t kMaxGridCoordinate = std::int64_t{1} << 29;

struct GridSegment {
  GridPoint a, b;
};

struct GraphEdge {
  std::uint32_t u = 0, v = 0;  // u < v
};

struct PenGraph {
  std::vector<GridPoint> vertices;       // numbered in order of first appearance in the pieces
  std::vector<GraphEdge> edges;          // ordered by u, then first appearance; no duplicates, no loops
  std::vector<std::uint32_t> degree;     // per vertex
  std::vector<std::uint32_t> component;  // per vertex; components numbered by their lowest vertex
  std::size_t components = 0;
  std::vector<std::uint32_t> odd;            // odd-degree vertices, increasing
  std::vector<std::uint32_t> component_odd;  // per component: how many odd vertices
  std::size_t lift_lower_bound = 0;          // Σ over components of max(1, odd / 2)
};

// Builds the graph of non-degenerate segments (a ≠ b, coordinates within ±kMaxGridCoordinate). `threads`
// as for parallel_chunks (core/parallel.hpp): 1 on this thread, 0 the caller's arena; the same graph for
// any value.
PenGraph build_pen_graph(std::span<const GridSegment> segments, double tolerance, unsigned threads = 1);

// Fills degree, component, odd, component_odd and lift_lower_bound from vertices and edges.
void compute_graph_structure(PenGraph& g);

}  // namespace hlr::plan
