#include "runtime/base/heap_warmer.hpp"

#include <cstdlib>  // defines __GLIBC__ under glibc

#include "runtime/base/sanitizer_allocator.hpp"

#if defined(__GLIBC__) && defined(__linux__) && !defined(HLR_OWN_ALLOCATOR)
#include <malloc.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <thread>
#define HLR_WARM_HEAP 1
#endif

namespace hlr::runtime {

#if defined(HLR_WARM_HEAP) && defined(MADV_POPULATE_WRITE)
namespace {

// Two huge pages past the heap's use: enough for the next few allocations of an import or a frame (a
// larger margin gained little more — fandisk 39.8 ms with 4 MiB, 40.2 with 8 — and the peak grows by it).
constexpr std::uintptr_t kAhead = std::uintptr_t{4} << 20;
constexpr std::uintptr_t kChunk = std::uintptr_t{2} << 20;  // a huge page: the heap's unit of faulting

void keep_ahead() {
  // The lowest priority: this thread takes only time no other thread wants.
  ::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 19);
  std::uintptr_t populated = 0;  // faulted in below this
  for (int idle = 0;;) {
    // The main arena is the heap below the program break; its top chunk (keepcost) is what no
    // allocation has reached yet. (Memory is never handed back, keep_freed_memory(): the break does not
    // move down.)
    const auto brk = reinterpret_cast<std::uintptr_t>(::sbrk(0));
    const struct mallinfo2 info = ::mallinfo2();
    const std::uintptr_t used = brk - std::min<std::uintptr_t>(info.keepcost, brk);
    const std::uintptr_t want = std::min(brk, used + kAhead) / kChunk * kChunk;
    bool worked = false;
    for (std::uintptr_t at = std::max(populated, used / kChunk * kChunk); at + kChunk <= want; at += kChunk) {
      if (::madvise(reinterpret_cast<void*>(at), kChunk, MADV_POPULATE_WRITE) != 0 && errno == EINVAL)
        return;  // a kernel without it
      populated = at + kChunk;
      worked = true;
    }
    idle = worked ? 0 : idle + 1;
    // Every quarter millisecond while the heap grows; once it has stopped, less and less often (a REPL
    // waiting for its next line wakes this thread ten times a second).
    std::this_thread::sleep_for(std::chrono::microseconds(idle < 200 ? 250 : idle < 400 ? 10'000 : 100'000));
  }
}

}  // namespace

void warm_heap_ahead() { std::thread(keep_ahead).detach(); }
#else
void warm_heap_ahead() {}
#endif

}  // namespace hlr::runtime
