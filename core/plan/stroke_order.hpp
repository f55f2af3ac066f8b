// Ordering and orienting the strokes of one pen and layer to cut pen-up travel.
//
// The tour runs from `start` through every stroke to `end` (or ends anywhere when `end_free`: the next
// pen's strokes start where this one stops). Open strokes may be drawn either way; closed strokes may also
// be entered at any of their vertices (they are rotated to start there).
//   * order_greedy: nearest entry point next (a k-d tree with deletion over every possible entry point,
//     each search starting bottom-up from the leaf where the pen stands), O(n log n).
//   * order_exact: Held–Karp over (strokes, entry choice) for small groups — the optimum for the given
//     strokes.
//   * improve_order: 2-opt (segment reversal, which also reverses the strokes in it) and Or-opt (moving
//     one to three consecutive strokes elsewhere, either way round) driven by nearest-neighbour lists of
//     the stroke end points (5 each; 8 below 16 384 strokes, 31 below 64; built once, or
//     taken from the odd-vertex matching) and a work queue, then each closed stroke re-entered at its best
//     vertex; a second round if any was. The tour is a cycle closed by a pseudo-stroke from `end` to `start`,
//     kept in a circular array where a move rewrites the shorter of the two arcs, and moves rewriting more
//     than 25 000 positions are skipped (windowed). Work is capped in proportion to the stroke count and
//     never measured in time, so the result depends only on the input.
#pragma once

#include <cstddef>
#include <vector>

#include "core/plan/euler_strokes.hpp"
#include "core/plan/kd_tree.hpp"

namespace hlr::plan {

struct TourEnds {
  Pt start;
  Pt end;
  bool end_free = false;
};

// Travel with the pen up, in grid units: start → first stroke, between strokes, last stroke → end.
double tour_travel(const std::vector<GridStroke>& strokes, const std::vector<GridPoint>& vertices,
                   const TourEnds& ends);

void order_greedy(std::vector<GridStroke>& strokes, const std::vector<GridPoint>& vertices,
                  const TourEnds& ends);

// Follows the Euler circuits: the strokes cut from one augmented circuit (euler_strokes(), consecutive,
// in circuit order) are drawn in that cyclic order — each pen-up move between them is one of the pairing's
// virtual edges — and the circuits are taken nearest entry first, each entered at the stroke start (either
// way round) nearest the pen, which drops the virtual edge there. O(n log n).
void order_circuits(std::vector<GridStroke>& strokes, const std::vector<GridPoint>& vertices,
                    const TourEnds& ends);

// Largest problems order_exact() takes: strokes, and entry choices summed over the strokes.
inline constexpr std::size_t kExactOrderStrokes = 10;
inline constexpr std::size_t kExactOrderChoices = 48;
// Returns false (leaving the strokes alone) when the problem is larger than the limits above.
bool order_exact(std::vector<GridStroke>& strokes, const std::vector<GridPoint>& vertices,
                 const TourEnds& ends);

struct ImproveResult {
  std::size_t moves = 0;  // improving 2-opt, Or-opt and re-entry moves applied
  std::size_t work = 0;   // candidate evaluations plus array elements rewritten
  bool capped = false;    // stopped by the work cap rather than by convergence
};

// Nearest-neighbour lists already computed over some graph vertices (min_weight_matching()'s over the odd
// vertices): lists[i·k … i·k + k) holds indices into `listed`, nearest first, padded with KdTree::kNone.
struct SharedNeighbours {
  const std::vector<std::uint32_t>* listed = nullptr;  // graph vertex numbers
  const std::vector<std::uint32_t>* lists = nullptr;
  std::size_t k = 0;
};

// The neighbour-list length improve_order() searches for a tour of `strokes` strokes (6 beyond 16 384).
std::size_t improve_list_length(std::size_t strokes);

// `work_per_stroke` bounds the work (see ImproveResult) at work_per_stroke · (strokes + 1). `shared`, when
// its vertices are exactly the open strokes' end points (no closed stroke) and its k is at least
// improve_list_length() (the first that many of each list are read), replaces the neighbour search (the
// pseudo-stroke's two ends then get theirs by a linear scan and appear in no other list).
ImproveResult improve_order(std::vector<GridStroke>& strokes, const std::vector<GridPoint>& vertices,
                            const TourEnds& ends, std::size_t work_per_stroke = 500,
                            const SharedNeighbours* shared = nullptr);

}  // namespace hlr::plan
