// Pairing the odd-degree vertices: a minimum-weight perfect matching under Euclidean distance. The virtual
// edges of the Euler pairing become pen-up moves when the strokes follow their circuit, so pairing close
// vertices shortens the travel.
//   * up to kExactMatchingLimit points: exact (dynamic programme over subsets, O(2^n · n));
//   * more: greedy over the 6-nearest-neighbour candidate pairs (shortest first), the leftovers paired
//     nearest-first, then 2-opt exchanges ((a,b),(c,d) → (a,c),(b,d)) over neighbour lists until none
//     gains or an iteration cap (proportional to n) is reached. Deterministic.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "core/plan/kd_tree.hpp"

namespace hlr::plan {

inline constexpr std::size_t kExactMatchingLimit = 16;

// Pairs of indices into `points` (an even number of them); each index appears once.
// `neighbours` (optional): beyond kExactMatchingLimit points, receives the lists the heuristic searched, of
// length max(list_length, kMatchingNeighbours) (as all_k_nearest(points, that length, ·)); the
// heuristic uses the first kMatchingNeighbours of each, and a longer list serves the order's local search
// (improve_order) without a second search. Otherwise cleared. `threads` as for all_k_nearest: the same
// pairs for any value.
inline constexpr std::size_t kMatchingNeighbours = 6;
std::vector<std::pair<std::uint32_t, std::uint32_t>> min_weight_matching(
    const std::vector<Pt>& points, std::vector<std::uint32_t>* neighbours = nullptr,
    std::size_t list_length = kMatchingNeighbours, unsigned threads = 1);

// The exact optimum's weight, by the same dynamic programme (n ≤ 20), for tests.
double exact_matching_weight(const std::vector<Pt>& points);

}  // namespace hlr::plan
