// Faces told apart by their cycles of vertices: an import drops a face whose cycle (either direction)
// repeats an earlier face's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <vector>

namespace hlr::stdlib::mesh_detail {

// The canonical form of a ring's cycle: from its smallest vertex, in the direction that reads smaller.
void canonical_cycle(const std::vector<std::uint32_t>& ring, std::vector<std::uint32_t>& out);

// A hash of a canonical cycle.
std::uint64_t cycle_hash(std::span<const std::uint32_t> cycle);

// cycle_hash of the canonical cycle of a triangle of three distinct vertices, without vectors: most faces
// of a scan are such.
std::uint64_t triangle_cycle_hash(std::uint32_t a, std::uint32_t b, std::uint32_t c);

// Faces by the hash of their cycle of vertices. A slot holds 8 bytes (the hash's top half as a
// fingerprint, the face), so the table of a large mesh stays in cache; open addressing, like
// ExactPointIndex. Faces are numbered in 32 bits: a file of 2^32 faces could not be held anyway.
class FaceCycleSet {
 public:
  explicit FaceCycleSet(std::size_t expected = 0);
  void prefetch(std::uint64_t hash) const {
    __builtin_prefetch(&slots_[static_cast<std::size_t>(hash) & (slots_.size() - 1)]);
  }
  // The first stored face whose cycle `same` confirms, or `face` (now stored) when none is.
  template <typename Same>
  std::size_t insert(std::uint64_t hash, std::size_t face, const Same& same) {
    // Sized at construction for every face, so at most half full (the fingerprints cannot be rehashed).
    if (2 * (size_ + 1) > slots_.size()) throw std::logic_error("FaceCycleSet: more faces than expected");
    const std::size_t mask = slots_.size() - 1;
    const auto fingerprint = static_cast<std::uint32_t>(hash >> 32);
    for (std::size_t s = static_cast<std::size_t>(hash) & mask;; s = (s + 1) & mask) {
      if (slots_[s].face == kEmpty) {
        slots_[s] = {fingerprint, static_cast<std::uint32_t>(face)};
        ++size_;
        return face;
      }
      if (slots_[s].fingerprint == fingerprint && same(slots_[s].face)) return slots_[s].face;
    }
  }

 private:
  struct Slot {
    std::uint32_t fingerprint, face;
  };
  static constexpr std::uint32_t kEmpty = 0xffffffffu;
  std::vector<Slot> slots_;
  std::size_t size_ = 0;
};

// Whether two of faces 0 … n − 1 have the same cycle: hashes[f] is the cycle_hash of face f's canonical
// cycle, and same_cycle(a, b) tells whether faces a and b have the same cycle (asked only where their
// hashes' top halves agree, from any thread). The faces are shared out over the cores by their hashes,
// each share looked up in a set of its own.
bool any_repeated_cycle(std::span<const std::uint64_t> hashes,
                        const std::function<bool(std::size_t, std::size_t)>& same_cycle);

}  // namespace hlr::stdlib::mesh_detail
