// A stable sort of items by bits [low_bit, high_bit) of a 64-bit key (the bits above must be zero): radix
// passes of 16 bits, or a comparison sort for few items, where the passes' 65 536 counters cost more than
// the work. The pen planner's sorts of packed coordinates and of candidate lengths both use it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hlr::plan {

inline constexpr std::size_t kRadixSortMin = 4096;

template <typename T, typename KeyOf>
void stable_sort_by_key_bits(std::vector<T>& items, KeyOf key_of, int low_bit, int high_bit) {
  if (items.size() < kRadixSortMin) {
    std::stable_sort(items.begin(), items.end(),
                     [&](const T& a, const T& b) { return (key_of(a) >> low_bit) < (key_of(b) >> low_bit); });
    return;
  }
  std::vector<T> tmp(items.size());
  std::vector<std::uint32_t> count(65537);
  for (int shift = low_bit; shift < high_bit; shift += 16) {
    std::fill(count.begin(), count.end(), 0u);
    for (const T& item : items) ++count[((key_of(item) >> shift) & 0xffffu) + 1];
    for (std::size_t b = 1; b < count.size(); ++b) count[b] += count[b - 1];
    for (const T& item : items) tmp[count[(key_of(item) >> shift) & 0xffffu]++] = item;
    items.swap(tmp);
  }
}

}  // namespace hlr::plan
