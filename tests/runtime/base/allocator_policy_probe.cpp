// For tests/runtime/base/allocator_policy.sh: says "start" on stderr each time main() begins, then prints
// GLIBC_TUNABLES as the process sees it after heap_on_huge_pages().
#include <cstdio>
#include <cstdlib>

#include "runtime/base/allocator_policy.hpp"

int main(int /*argc*/, char** argv) {
  std::fputs("start\n", stderr);
  hlr::runtime::heap_on_huge_pages(argv);
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::printf("%s\n", tunables ? tunables : "");
  return 0;
}
