// Something derived from a solid — where its faces cross, its corner normals — computed the first time it is
// asked for and kept with it: solids are immutable and shared between frames, so a static mesh pays once.
// Thread-safe; a copy of a solid starts without it, so code that copies a solid and edits the copy never
// sees a stale one.
#pragma once

#include <atomic>

namespace hlr {

template <typename T>
class DerivedCache {
 public:
  DerivedCache() = default;
  DerivedCache(const DerivedCache&) {}
  DerivedCache& operator=(const DerivedCache&) {
    replace(nullptr);
    return *this;
  }
  DerivedCache(DerivedCache&& other) noexcept : value_(other.value_.exchange(nullptr)) {}
  DerivedCache& operator=(DerivedCache&& other) noexcept {
    replace(other.value_.exchange(nullptr));
    return *this;
  }
  ~DerivedCache() { delete value_.load(); }

  // The kept value, or compute()'s, kept. Two threads may both compute; the result does not depend on
  // which one's is kept.
  template <typename Compute>
  const T& get(Compute&& compute) const {
    if (const T* kept = value_.load(std::memory_order_acquire)) return *kept;
    const T* mine = new T(compute());
    const T* expected = nullptr;
    if (value_.compare_exchange_strong(expected, mine, std::memory_order_acq_rel)) return *mine;
    delete mine;
    return *expected;
  }

 private:
  void replace(const T* value) { delete value_.exchange(value); }
  mutable std::atomic<const T*> value_{nullptr};
};

}  // namespace hlr
