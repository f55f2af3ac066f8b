#include "runtime/base/allocator_policy.hpp"

#include <cstdlib>  // defines __GLIBC__ under glibc
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#include <unistd.h>
#endif

#include "runtime/base/heap_pages.hpp"
#include "runtime/base/sanitizer_allocator.hpp"

namespace hlr::runtime {

void keep_freed_memory() {
#if defined(__GLIBC__)
  constexpr int kLargestMmapThreshold = 32 << 20;  // glibc refuses more (HEAP_MAX_SIZE / 2 on 64 bits)
  constexpr int kNeverTrim = -1;                   // as an unsigned size: no trimming at all
  // A thread's arena takes its heaps of 64 MiB whole rather than growing them a little at a time: each
  // growth was a system call, and on huge pages a part-grown heap's tail fell back to 4 KiB pages (the
  // 64 000-box city's `check`, evaluated on a thread, 0.97 → 0.59 s). Address space only: what is not
  // touched costs nothing.
  constexpr int kTopPad = 64 << 20;
  mallopt(M_MMAP_THRESHOLD, kLargestMmapThreshold);
  mallopt(M_TRIM_THRESHOLD, kNeverTrim);
  mallopt(M_TOP_PAD, kTopPad);
  // One arena for every thread: what the import frees on one thread is reused by the frame's parts on
  // another, where each thread's own arena took fresh pages for them (and kept its own partly used huge
  // pages). The bunny's run 78 → 52 MB; the 10⁶-triangle torus 637 → 447 MB and 1.8 → 1.1 s, its system
  // time 771 → 75 ms. The engine allocates little inside its parallel loops (some 11 000 blocks a bunny
  // frame, the small ones from each thread's cache), so the shared lock costs nothing measurable.
  mallopt(M_ARENA_MAX, 1);
#endif
}

void heap_on_huge_pages(char** argv) {
#if defined(__GLIBC__) && !defined(HLR_OWN_ALLOCATOR)
  constexpr const char* kVariable = "GLIBC_TUNABLES";
  const char* before = std::getenv("GLIBC_TUNABLES");  // spelled out: the manual's test looks for it
  const std::string kept = before ? before : "";
  if (kept.find(kHugetlbTunable) != std::string::npos) return;
  // Small pages are glibc's own default: no second start for them.
  if (host_takes_back_free_memory()) return;
  const std::string asked = kept + (kept.empty() ? "" : ":") + kHugePages;
  if (::setenv(kVariable, asked.c_str(), 1) != 0) return;
  ::execv("/proc/self/exe", argv);
  // Still here: no /proc. Go on as started, and leave the environment as it was for what we run.
  if (before)
    ::setenv(kVariable, kept.c_str(), 1);
  else
    ::unsetenv(kVariable);
#else
  (void)argv;
#endif
}

}  // namespace hlr::runtime
