#include "stdlib/face_cycles.hpp"

#include <algorithm>
#include <bit>

#include "core/parallel.hpp"

namespace hlr::stdlib::mesh_detail {

void canonical_cycle(const std::vector<std::uint32_t>& ring, std::vector<std::uint32_t>& out) {
  const std::size_t n = ring.size();
  const std::size_t m = static_cast<std::size_t>(std::min_element(ring.begin(), ring.end()) - ring.begin());
  auto step = [n](std::size_t i, bool forward) {
    return forward ? (i + 1 == n ? 0 : i + 1) : (i == 0 ? n - 1 : i - 1);
  };
  bool forward = true;
  for (std::size_t k = 1, i = step(m, true), j = step(m, false); k < n;
       ++k, i = step(i, true), j = step(j, false))
    if (ring[i] != ring[j]) {
      forward = ring[i] < ring[j];
      break;
    }
  out.clear();
  for (std::size_t k = 0, i = m; k < n; ++k, i = step(i, forward)) out.push_back(ring[i]);
}

std::uint64_t cycle_hash(std::span<const std::uint32_t> cycle) {
  std::uint64_t h = cycle.size() * 0x9E3779B97F4A7C15ull;
  for (std::uint32_t v : cycle) h = (h ^ v) * 0xBF58476D1CE4E5B9ull, h ^= h >> 31;
  return h;
}

std::uint64_t triangle_cycle_hash(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  // From the smallest vertex, towards the smaller of its two neighbours (they differ).
  const std::uint32_t ring[3] = {a, b, c};
  const int m = a < b ? (a < c ? 0 : 2) : (b < c ? 1 : 2);
  const std::uint32_t next = ring[(m + 1) % 3], previous = ring[(m + 2) % 3];
  const std::uint32_t cycle[3] = {ring[m], std::min(next, previous), std::max(next, previous)};
  return cycle_hash(cycle);
}

FaceCycleSet::FaceCycleSet(std::size_t expected)
    : slots_(std::bit_ceil(std::max<std::size_t>(16, 2 * expected)), Slot{0, kEmpty}) {}

bool any_repeated_cycle(std::span<const std::uint64_t> hashes,
                        const std::function<bool(std::size_t, std::size_t)>& same_cycle) {
  // Four shares, by two bits of the hash that neither a set's slot (its low bits, for sets of fewer than
  // 2^30 slots) nor its fingerprint (the top half) reads: equal cycles fall in one share. The answer does
  // not depend on how many cores take part.
  constexpr std::size_t kShares = 4;
  auto share_of = [](std::uint64_t hash) { return static_cast<std::size_t>(hash >> 30) & (kShares - 1); };
  const std::size_t n = hashes.size();
  char repeated[kShares] = {};
  parallel_chunks(kShares, threads_for(n, 8192, 0), [&](std::size_t share) {
    std::size_t count = 0;
    for (std::uint64_t h : hashes) count += share_of(h) == share;
    FaceCycleSet seen(count);
    for (std::size_t f = 0; f < n; ++f) {
      if (share_of(hashes[f]) != share) continue;
      if (seen.insert(hashes[f], f, [&](std::size_t e) { return same_cycle(e, f); }) != f) {
        repeated[share] = 1;
        return;
      }
    }
  });
  return std::any_of(std::begin(repeated), std::end(repeated), [](char r) { return r != 0; });
}

}  // namespace hlr::stdlib::mesh_detail
