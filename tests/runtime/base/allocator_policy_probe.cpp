// For tests/runtime/base/allocator_policy.sh: says "start" on stderr each time main() begins, then prints
// GLIBC_TUNABLES as the process sees it after heap_on_huge_pages(). With `warm` or `cold`, it then keeps
// freed memory, starts the heap warmer (`warm` only) and says whether the huge page just past the heap's
// use — which this program never touches — becomes resident within five seconds ("warmed") or not
// ("cold"; `cold` waits a quarter of a second).
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "runtime/base/allocator_policy.hpp"
#include "runtime/base/heap_warmer.hpp"

namespace {

bool page_past_use_resident() {
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  const auto brk = reinterpret_cast<std::uintptr_t>(::sbrk(0));
  const struct mallinfo2 info = ::mallinfo2();
  const std::uintptr_t first = (brk - info.keepcost + kHuge - 1) / kHuge * kHuge;
  if (first + kHuge > brk) return false;
  const long page = ::sysconf(_SC_PAGESIZE);
  unsigned char resident[1] = {0};
  // The last small page of that huge page: resident only if something faulted it in.
  const std::uintptr_t last = first + kHuge - static_cast<std::uintptr_t>(page);
  return ::mincore(reinterpret_cast<void*>(last), static_cast<std::size_t>(page), resident) == 0 &&
         (resident[0] & 1) != 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::fputs("start\n", stderr);
  hlr::runtime::heap_on_huge_pages(argv);
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::printf("%s\n", tunables ? tunables : "");
  if (argc < 2) return 0;
  const bool warm = std::strcmp(argv[1], "warm") == 0;
  hlr::runtime::keep_freed_memory();
  void* volatile some = std::malloc(3 << 20);  // more than the first heap holds: it grows by its top pad
  if (warm) hlr::runtime::warm_heap_ahead();
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(warm ? 5000 : 250);
  bool resident = false;
  while (!(resident = page_past_use_resident()) && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::printf("%s\n", resident ? "warmed" : "cold");
  std::free(some);
  return 0;
}
