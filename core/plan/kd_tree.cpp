#include "core/plan/kd_tree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include "core/parallel.hpp"
#include "core/tolerance.hpp"

namespace hlr::plan {
namespace {
// Plain (not value-initialised) scratch entries: the query arrays live on the stack, uncleared.
// all_k_nearest() compares every pair up to this many points.
constexpr std::size_t kBruteForceNearest = 128;

struct Scored {
  double d;
  std::uint32_t i;
  bool operator<(const Scored& o) const { return d != o.d ? d < o.d : i < o.i; }
};
}  // namespace

KdTree::KdTree(const std::vector<Pt>& points) {
  const std::uint32_t n = static_cast<std::uint32_t>(points.size());
  leaf_.assign(n, kNone);
  alive_.assign(n, 1);
  if (!n) return;
  // Partition a contiguous copy (point and index together) rather than indices into `points`.
  struct Item {
    Pt p;
    std::uint32_t index;
  };
  std::vector<Item> items(n);
  for (std::uint32_t i = 0; i < n; ++i) items[i] = {points[i], i};
  nodes_.reserve(2 * (n / kLeafSize + 1) + 1);
  nodes_.push_back(Node{0, 0, 0, 0, 0, n, kNone, kNone, kNone, n});
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const std::uint32_t id = stack.back();
    stack.pop_back();
    const std::uint32_t lo = nodes_[id].lo, hi = nodes_[id].hi;
    double xmin = items[lo].p.x, xmax = xmin, ymin = items[lo].p.y, ymax = ymin;
    for (std::uint32_t i = lo + 1; i < hi; ++i) {
      const Pt p = items[i].p;
      xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
      ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
    }
    nodes_[id].xmin = xmin, nodes_[id].ymin = ymin, nodes_[id].xmax = xmax, nodes_[id].ymax = ymax;
    if (hi - lo <= kLeafSize) {
      for (std::uint32_t i = lo; i < hi; ++i) leaf_[i] = id;
      continue;
    }
    const bool by_y = (ymax - ymin) > (xmax - xmin);
    const std::uint32_t mid = lo + (hi - lo) / 2;
    // The split need not break ties (queries break them by index; nth_element itself is deterministic).
    if (by_y)
      std::nth_element(items.begin() + lo, items.begin() + mid, items.begin() + hi,
                       [](const Item& a, const Item& b) { return a.p.y < b.p.y; });
    else
      std::nth_element(items.begin() + lo, items.begin() + mid, items.begin() + hi,
                       [](const Item& a, const Item& b) { return a.p.x < b.p.x; });
    const std::uint32_t l = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(Node{0, 0, 0, 0, lo, mid, kNone, kNone, id, mid - lo});
    nodes_.push_back(Node{0, 0, 0, 0, mid, hi, kNone, kNone, id, hi - mid});
    nodes_[id].left = l;
    nodes_[id].right = l + 1;
    stack.push_back(l + 1);
    stack.push_back(l);
  }
  points_.resize(n);
  index_.resize(n);
  position_.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    points_[i] = items[i].p;
    index_[i] = items[i].index;
    position_[items[i].index] = i;
  }
}

void KdTree::erase(std::uint32_t index) {
  const std::uint32_t at = position_[index];
  if (!alive_[at]) return;
  alive_[at] = 0;
  for (std::uint32_t id = leaf_[at]; id != kNone; id = nodes_[id].parent) --nodes_[id].alive;
}

void KdTree::search_subtree(std::uint32_t root, Pt q, double& best, std::uint32_t& best_index) const {
  Scored stack[96];  // (box distance², node)
  int top = 0;
  stack[top++] = {box_dist2(nodes_[root], q), root};
  while (top) {
    const auto [bound, id] = stack[--top];
    if (bound > best) continue;
    const Node& n = nodes_[id];
    if (!n.alive) continue;
    if (n.left == kNone) {
      for (std::uint32_t i = n.lo; i < n.hi; ++i) {
        if (!alive_[i]) continue;
        const double d = dist2(q, points_[i]);
        if (d < best || (d == best && index_[i] < best_index)) best = d, best_index = index_[i];
      }
      continue;
    }
    const double dl = box_dist2(nodes_[n.left], q), dr = box_dist2(nodes_[n.right], q);
    // Nearer child on top, so it is searched first.
    if (dl <= dr)
      stack[top++] = {dr, n.right}, stack[top++] = {dl, n.left};
    else
      stack[top++] = {dl, n.left}, stack[top++] = {dr, n.right};
  }
}

std::uint32_t KdTree::nearest(Pt q) const {
  double best = std::numeric_limits<double>::infinity();
  std::uint32_t best_index = kNone;
  if (nodes_.empty() || !nodes_[0].alive) return kNone;
  search_subtree(0, q, best, best_index);
  return best_index;
}

std::uint32_t KdTree::nearest(Pt q, std::uint32_t near_index) const {
  if (nodes_.empty() || !nodes_[0].alive || near_index >= position_.size()) return nearest(q);
  double best = std::numeric_limits<double>::infinity();
  std::uint32_t best_index = kNone;
  // The leaf of near_index, then the sibling subtree of every node on the way up: the whole tree once.
  for (std::uint32_t from = kNone, id = leaf_[position_[near_index]]; id != kNone;
       from = id, id = nodes_[id].parent) {
    const std::uint32_t root =
        from == kNone ? id : (nodes_[id].left == from ? nodes_[id].right : nodes_[id].left);
    search_subtree(root, q, best, best_index);
  }
  return best_index;
}

void KdTree::k_nearest(Pt q, std::size_t k, std::uint32_t exclude, std::vector<std::uint32_t>& out) const {
  out.clear();
  if (!k || nodes_.empty() || !nodes_[0].alive) return;
  // The best k so far, sorted by (distance², index); k is small, so insertion sort.
  Scored best[64];
  k = std::min<std::size_t>(k, 64);
  std::size_t have = 0;
  auto worst = [&] { return have < k ? std::numeric_limits<double>::infinity() : best[have - 1].d; };
  Scored stack[96];
  int top = 0;
  stack[top++] = {box_dist2(nodes_[0], q), 0};
  while (top) {
    const auto [bound, id] = stack[--top];
    if (bound > worst()) continue;
    const Node& n = nodes_[id];
    if (!n.alive) continue;
    if (n.left == kNone) {
      for (std::uint32_t i = n.lo; i < n.hi; ++i) {
        if (!alive_[i] || index_[i] == exclude) continue;
        const Scored e{dist2(q, points_[i]), index_[i]};
        if (have == k && !(e < best[have - 1])) continue;
        std::size_t j = have < k ? have++ : have - 1;
        while (j > 0 && e < best[j - 1]) best[j] = best[j - 1], --j;
        best[j] = e;
      }
      continue;
    }
    const double dl = box_dist2(nodes_[n.left], q), dr = box_dist2(nodes_[n.right], q);
    if (dl <= dr)
      stack[top++] = {dr, n.right}, stack[top++] = {dl, n.left};
    else
      stack[top++] = {dl, n.left}, stack[top++] = {dr, n.right};
  }
  for (std::size_t i = 0; i < have; ++i) out.push_back(best[i].i);
}

void all_k_nearest(const std::vector<Pt>& points, std::size_t k, std::vector<std::uint32_t>& out, bool exact,
                   unsigned threads) {
  constexpr std::uint32_t kNone = KdTree::kNone;
  const std::size_t n = points.size();
  k = std::min<std::size_t>(k, 64);
  out.assign(n * k, kNone);
  if (n < 2 || k == 0) return;
  if (n <= kBruteForceNearest) {  // every pair: cheaper than setting up a grid for a few points
    std::vector<Scored> all(n - 1);
    for (std::uint32_t i = 0; i < n; ++i) {
      std::size_t m = 0;
      for (std::uint32_t j = 0; j < n; ++j)
        if (j != i) all[m++] = {dist2(points[i], points[j]), j};
      const std::size_t keep = std::min(k, all.size());
      std::partial_sort(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(keep), all.end());
      for (std::size_t m2 = 0; m2 < keep; ++m2) out[i * k + m2] = all[m2].i;
    }
    return;
  }
  double xmin = points[0].x, xmax = xmin, ymin = points[0].y, ymax = ymin;
  for (const Pt& p : points) {
    xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
    ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
  }
  const double w = std::max(xmax - xmin, Tolerance::kPlanGridExtent),
               h = std::max(ymax - ymin, Tolerance::kPlanGridExtent);
  double cell = std::sqrt(0.5 * std::max(w, h / 1e6) * std::max(h, w / 1e6) / static_cast<double>(n));
  std::int64_t nx, ny;
  for (;;) {
    nx = static_cast<std::int64_t>(w / cell) + 1, ny = static_cast<std::int64_t>(h / cell) + 1;
    if (static_cast<double>(nx) * static_cast<double>(ny) <= 4.0 * static_cast<double>(n) + 4096) break;
    cell *= 1.5;
  }
  auto cx_of = [&](double x) {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>((x - xmin) / cell), 0, nx - 1);
  };
  auto cy_of = [&](double y) {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>((y - ymin) / cell), 0, ny - 1);
  };
  std::vector<std::uint32_t> start(static_cast<std::size_t>(nx * ny) + 1, 0), cell_of(n);
  for (std::size_t i = 0; i < n; ++i) {
    cell_of[i] = static_cast<std::uint32_t>(cy_of(points[i].y) * nx + cx_of(points[i].x));
    ++start[cell_of[i] + 1];
  }
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<Pt> cp(n);
  std::vector<std::uint32_t> ci(n);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t at = fill[cell_of[i]]++;
      cp[at] = points[i];
      ci[at] = i;
    }
  }
  // A ring search per point, limited on the first pass (kMaxRing rings, kCrowded points scanned); the
  // points it leaves undecided are finished without limits when few, else by a k-d tree.
  constexpr std::int64_t kMaxRing = 8;
  constexpr std::uint32_t kCrowded = 400;
  auto search = [&](std::size_t at, bool limited, Scored* best) {
    const std::uint32_t i = ci[at];
    const Pt q = cp[at];
    const std::int64_t cx = cx_of(q.x), cy = cy_of(q.y);
    std::size_t have = 0;
    std::uint32_t scanned = 0;
    auto scan = [&](std::int64_t x, std::int64_t y) {
      if (x < 0 || y < 0 || x >= nx || y >= ny) return;
      const std::size_t c = static_cast<std::size_t>(y * nx + x);
      scanned += start[c + 1] - start[c];
      for (std::uint32_t j = start[c]; j < start[c + 1]; ++j) {
        if (ci[j] == i) continue;
        const Scored e{dist2(q, cp[j]), ci[j]};
        if (have == k && !(e < best[have - 1])) continue;
        std::size_t m = have < k ? have++ : have - 1;
        while (m > 0 && e < best[m - 1]) best[m] = best[m - 1], --m;
        best[m] = e;
      }
    };
    for (std::int64_t r = 0;; ++r) {
      if (limited && (r > kMaxRing || scanned > kCrowded)) return false;
      if (r == 0) {
        scan(cx, cy);
      } else {
        for (std::int64_t x = cx - r; x <= cx + r; ++x) scan(x, cy - r), scan(x, cy + r);
        for (std::int64_t y = cy - r + 1; y <= cy + r - 1; ++y) scan(cx - r, y), scan(cx + r, y);
      }
      // Everything outside rings 0…r is at least this far.
      const double edge = std::min({q.x - (xmin + static_cast<double>(cx - r) * cell),
                                    xmin + static_cast<double>(cx + r + 1) * cell - q.x,
                                    q.y - (ymin + static_cast<double>(cy - r) * cell),
                                    ymin + static_cast<double>(cy + r + 1) * cell - q.y});
      const bool covers_all = cx - r <= 0 && cy - r <= 0 && cx + r >= nx - 1 && cy + r >= ny - 1;
      if (covers_all || (have == k && (!exact ? r >= 1 : best[k - 1].d <= edge * edge))) break;
    }
    for (std::size_t m = 0; m < have; ++m) out[i * k + m] = best[m].i;
    return true;
  };
  // The first pass in parts of the points side by side (each query writes only its own list), the
  // undecided joined in part order. A query takes about half a microsecond: a part is about as long as
  // handing it to another core is worth (the bunny's 5 000 odd points were one part, 2.5 ms on one core).
  constexpr std::size_t kPart = 1024;
  std::vector<std::vector<std::uint32_t>> part_undecided((n + kPart - 1) / kPart);
  parallel_chunks(part_undecided.size(), threads_for(n, 2 * kPart, threads), [&](std::size_t part) {
    Scored best[64];
    for (std::size_t at = part * kPart; at < std::min(n, (part + 1) * kPart); ++at)
      if (!search(at, true, best)) part_undecided[part].push_back(static_cast<std::uint32_t>(at));
  });
  std::vector<std::uint32_t> undecided;  // positions in cell order
  for (const auto& u : part_undecided) undecided.insert(undecided.end(), u.begin(), u.end());
  if (undecided.size() <= n / 64 + 16) {
    Scored best[64];
    for (std::uint32_t at : undecided) search(at, false, best);
  } else {
    const KdTree tree(points);
    std::vector<std::uint32_t> found;
    for (std::uint32_t at : undecided) {
      tree.k_nearest(cp[at], k, ci[at], found);
      std::copy(found.begin(), found.end(), out.begin() + static_cast<std::ptrdiff_t>(ci[at] * k));
    }
  }
}

}  // namespace hlr::plan
