// A stable sort of 64-bit entries by the 30 bits from `first_bit` up: two counting passes of 15 bits each,
// linear where a comparison sort is n log n. For keys packed with what they sort (the self-crossing
// search's grid entries, an import's Morton codes with their vertex numbers).
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace hlr {

// `buffer` and `counts` are room the caller may keep between calls.
inline void sort_by_30_bits(std::vector<std::uint64_t>& entries, int first_bit,
                            std::vector<std::uint64_t>& buffer, std::vector<std::uint32_t>& counts) {
  buffer.resize(entries.size());
  counts.resize(1u << 15);
  for (const int shift : {first_bit, first_bit + 15}) {
    std::fill(counts.begin(), counts.end(), 0u);
    for (std::uint64_t e : entries) ++counts[(e >> shift) & 0x7fff];
    std::uint32_t sum = 0;
    for (std::uint32_t& c : counts) sum += std::exchange(c, sum);
    for (std::uint64_t e : entries) buffer[counts[(e >> shift) & 0x7fff]++] = e;
    entries.swap(buffer);
  }
}

inline void sort_by_30_bits(std::vector<std::uint64_t>& entries, int first_bit) {
  std::vector<std::uint64_t> buffer;
  std::vector<std::uint32_t> counts;
  sort_by_30_bits(entries, first_bit, buffer, counts);
}

}  // namespace hlr
