#include "core/first_touch.hpp"

#include <algorithm>
#include <cstdint>

#include "core/parallel.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace hlr {

void touch_pages(void* data, std::size_t bytes, unsigned threads) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  constexpr std::size_t kChunk = std::size_t{2} << 20;  // a huge page: the kernel's unit on the heap
  const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  if (data == nullptr || page == 0 || bytes < kChunk) return;  // small: not worth a system call
  // Whole pages inside the range only: the partial pages at its ends may hold other data.
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) / page * page;
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) / page * page;
  if (end <= begin) return;
  // Chunks on huge-page boundaries, so that no two threads fault the same huge page.
  const std::uintptr_t first = begin / kChunk * kChunk;
  const std::size_t chunks = (end - first + kChunk - 1) / kChunk;
  parallel_chunks(chunks, threads, [&](std::size_t k) {
    const std::uintptr_t from = std::max(begin, first + k * kChunk);
    const std::uintptr_t to = std::min(end, first + (k + 1) * kChunk);
    ::madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);  // a hint: failure is fine
  });
#else
  (void)data;
  (void)bytes;
  (void)threads;
#endif
}

}  // namespace hlr
