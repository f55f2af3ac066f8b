// A small open-addressing hash map from 64-bit keys to 32-bit values (linear probing, power-of-two
// capacity, load ≤ 1/2), for the pen planner's vertex, cell and edge keys. std::unordered_map would do;
// this one allocates
// once, not per key, and keeps each key beside its value (one cache miss per probe).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace hlr::plan {

class FlatIndex {
 public:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // never a key (callers pack keys below it)

  explicit FlatIndex(std::size_t expected = 16) {
    std::size_t cap = 16;
    while (cap < 2 * expected) cap *= 2;
    slots_.assign(cap, Slot{kEmpty, 0});
    mask_ = cap - 1;
  }

  std::size_t size() const { return size_; }

  // The value stored under `key`, or nullptr.
  const std::uint32_t* find(std::uint64_t key) const {
    for (std::size_t i = hash(key) & mask_;; i = (i + 1) & mask_) {
      if (slots_[i].key == key) return &slots_[i].value;
      if (slots_[i].key == kEmpty) return nullptr;
    }
  }

  // Inserts key → value unless the key is present; returns the stored value and whether it was inserted.
  std::pair<std::uint32_t, bool> insert(std::uint64_t key, std::uint32_t value) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    for (std::size_t i = hash(key) & mask_;; i = (i + 1) & mask_) {
      if (slots_[i].key == key) return {slots_[i].value, false};
      if (slots_[i].key == kEmpty) {
        slots_[i] = {key, value};
        ++size_;
        return {value, true};
      }
    }
  }

  // The stored value for `key`, inserting `value` first if absent (for in-place updates).
  std::uint32_t& at_or_insert(std::uint64_t key, std::uint32_t value) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    for (std::size_t i = hash(key) & mask_;; i = (i + 1) & mask_) {
      if (slots_[i].key == key) return slots_[i].value;
      if (slots_[i].key == kEmpty) {
        slots_[i] = {key, value};
        ++size_;
        return slots_[i].value;
      }
    }
  }

 private:
  static std::size_t hash(std::uint64_t x) {  // splitmix64's finaliser
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    x ^= x >> 31;
    return static_cast<std::size_t>(x);
  }

  struct Slot {
    std::uint64_t key;
    std::uint32_t value;
  };

  void grow() {
    std::vector<Slot> slots(slots_.size() * 2, Slot{kEmpty, 0});
    const std::size_t mask = slots.size() - 1;
    for (const Slot& s : slots_) {
      if (s.key == kEmpty) continue;
      std::size_t i = hash(s.key) & mask;
      while (slots[i].key != kEmpty) i = (i + 1) & mask;
      slots[i] = s;
    }
    slots_.swap(slots);
    mask_ = mask;
  }

  std::vector<Slot> slots_;  // key and value together: one cache line per probe
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

// Packs a point with |x|, |y| < 2^31 into a key below FlatIndex::kEmpty.
inline std::uint64_t pack_point_key(std::int64_t x, std::int64_t y) {
  return (static_cast<std::uint64_t>(x + (std::int64_t{1} << 31)) << 32) |
         static_cast<std::uint64_t>(y + (std::int64_t{1} << 31));
}

}  // namespace hlr::plan
