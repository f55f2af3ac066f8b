// Fresh memory is zeroed by the kernel when it is first touched, on the thread that touches it. On the
// machines measured that zeroing is slow (0.6 ms a megabyte on the 2-core CI machines), and a frame's
// lists, filled in parallel, were first touched by the one thread that sized them. These helpers touch
// a new list's pages on every thread that takes part before it is filled.
#pragma once

#include <cstddef>
#include <vector>

namespace hlr {

// Faults in the pages of [data, data + bytes) for writing, shared out as core/parallel.hpp's `threads`
// says. Only a hint: where the system cannot, the pages are faulted in when written.
void touch_pages(void* data, std::size_t bytes, unsigned threads);

// Resizes `v` to `n` value-initialised elements. When that needs new storage, its pages are touched as
// above first.
template <typename T>
void resize_touched(std::vector<T>& v, std::size_t n, unsigned threads) {
  if (n > v.capacity()) {
    std::vector<T> fresh;
    fresh.reserve(n);
    touch_pages(fresh.data(), n * sizeof(T), threads);
    fresh.assign(v.begin(), v.end());
    v.swap(fresh);
  }
  v.resize(n);
}

}  // namespace hlr
