#include "core/plan/odd_matching.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>

#include "core/plan/key_sort.hpp"
#include "core/tolerance.hpp"

namespace hlr::plan {
namespace {

using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

// dp[mask] = best matching of the points in mask, always pairing its lowest point first.
std::vector<double> subset_dp(const std::vector<Pt>& p, std::vector<std::uint8_t>* partner_of_lowest) {
  const std::size_t n = p.size();
  const std::size_t full = (std::size_t{1} << n) - 1;
  std::vector<double> dp(full + 1, std::numeric_limits<double>::infinity());
  if (partner_of_lowest) partner_of_lowest->assign(full + 1, 0);
  dp[0] = 0;
  // A set of an odd number of points has no perfect matching: skip those masks.
  for (std::size_t mask = 1; mask <= full; ++mask) {
    if (std::popcount(mask) % 2) continue;
    const int i = std::countr_zero(mask);
    const std::size_t rest = mask & ~(std::size_t{1} << i);
    double best = std::numeric_limits<double>::infinity();
    std::uint8_t best_j = 0;
    for (std::size_t r = rest; r; r &= r - 1) {
      const int j = std::countr_zero(r);
      const double c = dp[rest & ~(std::size_t{1} << j)] + dist(p[i], p[j]);
      if (c < best) best = c, best_j = static_cast<std::uint8_t>(j);
    }
    dp[mask] = best;
    if (partner_of_lowest) (*partner_of_lowest)[mask] = best_j;
  }
  return dp;
}

Pairs exact_matching(const std::vector<Pt>& p) {
  std::vector<std::uint8_t> partner;
  subset_dp(p, &partner);
  Pairs out;
  std::size_t mask = (std::size_t{1} << p.size()) - 1;
  while (mask) {
    const int i = std::countr_zero(mask);
    const int j = partner[mask];
    out.emplace_back(i, j);
    mask &= ~((std::size_t{1} << i) | (std::size_t{1} << j));
  }
  return out;
}

Pairs heuristic_matching(const std::vector<Pt>& p, std::vector<std::uint32_t>* neighbours,
                         std::size_t list_length, unsigned threads) {
  const std::uint32_t n = static_cast<std::uint32_t>(p.size());
  constexpr std::uint32_t kNone = ~0u;
  constexpr std::size_t kNeighbours = kMatchingNeighbours;
  const std::size_t stride = std::max(kNeighbours, list_length);
  std::vector<std::uint32_t> mate(n, kNone);
  // Neighbour lists (also used by the improvement pass); the matching reads the first kNeighbours of each.
  // Exact: the approximate lists (a few rings of a grid) cost the city 10³ a fifth of its pen-up saving.
  std::vector<std::uint32_t> nbr;
  all_k_nearest(p, stride, nbr, true, threads);
  // Candidate pairs, each once (from its lower end, or from the end whose list holds the other only),
  // sorted by length then by index: the key packs the length's float bits above the candidate's number.
  auto listed = [&](std::uint32_t a, std::uint32_t b) {
    const auto first = nbr.begin() + static_cast<std::ptrdiff_t>(a * stride);
    return std::find(first, first + kNeighbours, b) != first + kNeighbours;
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(static_cast<std::size_t>(n) * kNeighbours * 3 / 4 + 1);
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < kNeighbours; ++k) {
      const std::uint32_t j = nbr[static_cast<std::size_t>(i) * stride + k];
      if (j == kNone) break;
      if (i < j || !listed(j, i)) pairs.emplace_back(std::min(i, j), std::max(i, j));
    }
  std::vector<std::uint64_t> keys(pairs.size());
  for (std::size_t c = 0; c < pairs.size(); ++c) {
    const float d = static_cast<float>(dist(p[pairs[c].first], p[pairs[c].second]));
    keys[c] = (static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(d)) << 32) | c;
  }
  // Keys come in increasing candidate number, so a stable radix sort on the length bits alone (two
  // 16-bit passes) gives the same order as sorting the whole keys.
  stable_sort_by_key_bits(
      keys, [](std::uint64_t k) { return k; }, 32, 64);
  for (std::uint64_t key : keys) {
    const auto [a, b] = pairs[key & 0xffffffffu];
    if (mate[a] == kNone && mate[b] == kNone) {
      mate[a] = b;
      mate[b] = a;
    }
  }
  // Leftovers: nearest free point first, in index order.
  std::vector<Pt> left_points;
  std::vector<std::uint32_t> left;
  for (std::uint32_t i = 0; i < n; ++i)
    if (mate[i] == kNone) left.push_back(i), left_points.push_back(p[i]);
  KdTree tree(left_points);
  for (std::uint32_t li = 0; li < left.size(); ++li) {
    const std::uint32_t i = left[li];
    if (mate[i] != kNone) continue;
    tree.erase(li);
    const std::uint32_t lj = tree.nearest(p[i]);
    if (lj == KdTree::kNone) throw std::logic_error("min_weight_matching: odd point count");
    tree.erase(lj);
    const std::uint32_t j = left[lj];
    mate[i] = j;
    mate[j] = i;
  }
  // 2-opt exchanges over the neighbour lists.
  std::deque<std::uint32_t> queue;
  std::vector<char> queued(n, 1);
  for (std::uint32_t i = 0; i < n; ++i) queue.push_back(i);
  std::size_t budget = 50 * static_cast<std::size_t>(n) + 1000;
  while (!queue.empty() && budget) {
    const std::uint32_t a = queue.front();
    queue.pop_front();
    queued[a] = 0;
    const std::uint32_t ma = mate[a];
    const double dam = dist(p[a], p[ma]);
    for (std::size_t k = 0; k < kNeighbours && budget; ++k, --budget) {
      const std::uint32_t c = nbr[static_cast<std::size_t>(a) * stride + k];
      if (c == kNone) break;
      const double dac = dist(p[a], p[c]);
      if (dac >= dam) break;
      const std::uint32_t mc = mate[c];
      if (mc == a || c == ma) continue;
      const double gain = dam + dist(p[c], p[mc]) - dac - dist(p[ma], p[mc]);
      if (gain > Tolerance::kPlanMatchingGain * (dam + 1)) {
        mate[a] = c, mate[c] = a, mate[ma] = mc, mate[mc] = ma;
        for (std::uint32_t v : {a, c, ma, mc})
          if (!queued[v]) queued[v] = 1, queue.push_back(v);
        break;
      }
    }
  }
  Pairs out;
  out.reserve(n / 2);
  for (std::uint32_t i = 0; i < n; ++i)
    if (i < mate[i]) out.emplace_back(i, mate[i]);
  if (neighbours) neighbours->swap(nbr);
  return out;
}

}  // namespace

Pairs min_weight_matching(const std::vector<Pt>& points, std::vector<std::uint32_t>* neighbours,
                          std::size_t list_length, unsigned threads) {
  if (neighbours) neighbours->clear();
  if (points.size() % 2) throw std::invalid_argument("min_weight_matching: odd point count");
  if (points.empty()) return {};
  if (points.size() <= kExactMatchingLimit) return exact_matching(points);
  return heuristic_matching(points, neighbours, list_length, threads);
}

double exact_matching_weight(const std::vector<Pt>& points) {
  if (points.size() % 2 || points.size() > 20) throw std::invalid_argument("exact_matching_weight");
  if (points.empty()) return 0;
  return subset_dp(points, nullptr).back();
}

}  // namespace hlr::plan
