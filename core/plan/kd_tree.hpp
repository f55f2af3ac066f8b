// A static 2-D k-d tree over points with deletion, for nearest-neighbour queries of the pen planner
// (greedy stroke ordering, neighbour lists, matching). Nodes split the wider side of their bounding box
// at the median until at most kLeafSize points remain; every node keeps its bounding box and its count of
// live points, so deleted regions are skipped and far boxes pruned. Iterative throughout (no recursion).
// Ties are broken by the lower index, so results are deterministic.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

namespace hlr::plan {

struct Pt {
  double x = 0, y = 0;
};

inline double dist2(Pt a, Pt b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return dx * dx + dy * dy;
}
inline double dist(Pt a, Pt b) { return std::sqrt(dist2(a, b)); }

class KdTree {
 public:
  static constexpr std::uint32_t kNone = ~0u;
  static constexpr std::uint32_t kLeafSize = 32;

  explicit KdTree(const std::vector<Pt>& points);

  std::size_t alive() const { return nodes_.empty() ? 0 : nodes_[0].alive; }
  // The points' indices in tree order (spatially coherent): bulk queries in this order stay in cache.
  const std::vector<std::uint32_t>& tree_order() const { return index_; }
  // Removes point `index` (its index in the constructor's vector); removing twice is a no-op.
  void erase(std::uint32_t index);
  // The live point nearest to q (lowest index among equals), or kNone when none is left.
  std::uint32_t nearest(Pt q) const;
  // The same answer, searched bottom-up from the leaf of point `near_index` (live or not; any index is
  // valid): cheaper when that point is close to q (greedy chains of queries).
  std::uint32_t nearest(Pt q, std::uint32_t near_index) const;
  // Up to k live points nearest to q, nearest first (ties by index), skipping `exclude`; `out` is cleared.
  void k_nearest(Pt q, std::size_t k, std::uint32_t exclude, std::vector<std::uint32_t>& out) const;

 private:
  struct Node {
    double xmin, ymin, xmax, ymax;
    std::uint32_t lo, hi;       // its points: positions [lo, hi) in tree order
    std::uint32_t left, right;  // children (kNone for a leaf)
    std::uint32_t parent;
    std::uint32_t alive;
  };
  // Searches the subtree at `root` for a live point nearer than `best` (ties: lower index), updating
  // best and best_index.
  void search_subtree(std::uint32_t root, Pt q, double& best, std::uint32_t& best_index) const;
  static double box_dist2(const Node& n, Pt q) {
    const double dx = q.x < n.xmin ? n.xmin - q.x : (q.x > n.xmax ? q.x - n.xmax : 0.0);
    const double dy = q.y < n.ymin ? n.ymin - q.y : (q.y > n.ymax ? q.y - n.ymax : 0.0);
    return dx * dx + dy * dy;
  }

  std::vector<Node> nodes_;
  std::vector<Pt> points_;               // in tree order
  std::vector<std::uint32_t> index_;     // tree position → original index
  std::vector<std::uint32_t> position_;  // original index → tree position
  std::vector<std::uint32_t> leaf_;      // tree position → its leaf node
  std::vector<std::uint8_t> alive_;      // per tree position
};

// For every point, up to k nearest other points (nearest first, ties by index) into
// out[i·k … i·k + k), padded with KdTree::kNone. Up to 128 points, every pair is compared; beyond, a uniform
// grid of about two cells per point answers most queries from the cells within a few rings around the point;
// a point in a crowded neighbourhood, or whose k-th neighbour lies beyond a few rings, asks a k-d tree. Same
// result as KdTree::k_nearest for every point. With `exact` false the search stops as soon as k points are
// found in the rings 0…r around the point's cell (r ≥ 1): nearly always the true k nearest, occasionally a
// slightly farther one — candidate lists for heuristics, at about half the cost. `threads` as for
// parallel_chunks (core/parallel.hpp); the same lists for any value.
void all_k_nearest(const std::vector<Pt>& points, std::size_t k, std::vector<std::uint32_t>& out,
                   bool exact = true, unsigned threads = 1);

}  // namespace hlr::plan
