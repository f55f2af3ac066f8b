// ExactPointIndex (mesh_detail.hpp): positions told apart bit for bit, -0 and +0 alike.
#include <bit>

#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib::mesh_detail {

ExactPointIndex::ExactPointIndex(std::size_t expected)
    : slots_(std::bit_ceil(std::max<std::size_t>(16, 2 * expected)), Slot{0, kEmpty}) {}

ExactPointIndex::Key ExactPointIndex::key_of(Point3 p) {
  return {std::bit_cast<std::uint64_t>(p.x + 0.0), std::bit_cast<std::uint64_t>(p.y + 0.0),
          std::bit_cast<std::uint64_t>(p.z + 0.0)};  // -0 + 0 = +0
}

std::uint64_t ExactPointIndex::hash_of(const Key& key) {
  std::uint64_t h = key[0] * 0x9E3779B97F4A7C15ull;
  h = (h ^ (h >> 29) ^ key[1]) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 32) ^ key[2]) * 0x94D049BB133111EBull;
  return h ^ (h >> 31);
}

}  // namespace hlr::stdlib::mesh_detail
