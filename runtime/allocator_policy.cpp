#include "runtime/allocator_policy.hpp"

#include <cstdlib>  // defines __GLIBC__ under glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace hlr::runtime {

void keep_freed_memory() {
#if defined(__GLIBC__)
  constexpr int kLargestMmapThreshold = 32 << 20;  // glibc refuses more (HEAP_MAX_SIZE / 2 on 64 bits)
  constexpr int kNeverTrim = -1;                   // as an unsigned size: no trimming at all
  mallopt(M_MMAP_THRESHOLD, kLargestMmapThreshold);
  mallopt(M_TRIM_THRESHOLD, kNeverTrim);
#endif
}

}  // namespace hlr::runtime
