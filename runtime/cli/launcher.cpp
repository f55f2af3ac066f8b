// hlrscript: starts the engine (hlrscript-engine, runtime/cli/main.cpp) with its heap on transparent huge
// pages, or on small ones on a virtual machine whose host takes back freed memory (heap_pages.hpp). glibc
// reads glibc.malloc.hugetlb only when a process starts; elsewhere, a large drawing spent a quarter to two
// fifths of its time on first touches of 4 KiB pages (bench/README.md). The engine used to execute itself
// again to get it, loading its 32 shared libraries twice (12 ms of a 26 ms start); this program links
// nothing but the C library, so the second start is the only full one. The process stays the same (exec):
// its id, signals, standard streams and exit status are the engine's.
#include <limits.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "runtime/base/heap_pages.hpp"

namespace {

constexpr const char* kTunables = "GLIBC_TUNABLES";

// Adds the heap's page setting (heap_pages.hpp) to GLIBC_TUNABLES unless a hugetlb setting (the user's
// own) is there.
void choose_heap_pages() {
  const char* before = std::getenv(kTunables);
  if (before != nullptr && std::strstr(before, hlr::runtime::kHugetlbTunable) != nullptr) return;
  const char* setting = hlr::runtime::heap_page_tunable();
  if (before == nullptr || *before == '\0') {
    ::setenv(kTunables, setting, 1);
    return;
  }
  const std::size_t size = std::strlen(before) + 1 + std::strlen(setting) + 1;
  char* joined = static_cast<char*>(std::malloc(size));
  if (joined == nullptr) return;  // go on without: slower, not wrong
  std::snprintf(joined, size, "%s:%s", before, setting);
  ::setenv(kTunables, joined, 1);
  std::free(joined);
}

// Whether `path` is `folder` + `name` and names an executable file.
bool engine_at(char (&path)[PATH_MAX], const char* folder, const char* name) {
  const int n = std::snprintf(path, sizeof path, "%s%s", folder, name);
  return n > 0 && static_cast<std::size_t>(n) < sizeof path && ::access(path, X_OK) == 0;
}

}  // namespace

int main(int, char** argv) {
  // The engine lies beside this program's folder (an installed tree: bin/ and libexec/, which may have
  // been moved together) or in it (the build folder).
  char self[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) {
    std::fprintf(stderr,
                 "hlrscript: cannot tell where this program is (/proc/self/exe: %s); run "
                 "hlrscript-engine from its libexec folder instead\n",
                 std::strerror(errno));
    return 127;
  }
  self[n] = '\0';
  char* slash = std::strrchr(self, '/');
  if (slash != nullptr) slash[1] = '\0';
  char engine[PATH_MAX];
  if (!engine_at(engine, self, "../libexec/hlrscript-engine") &&
      !engine_at(engine, self, "hlrscript-engine")) {
    std::fprintf(stderr,
                 "hlrscript: the engine is missing: neither %s../libexec/hlrscript-engine nor "
                 "%shlrscript-engine can be run; reinstall hlrscript\n",
                 self, self);
    return 127;
  }
  choose_heap_pages();
  ::execv(engine, argv);
  std::fprintf(stderr, "hlrscript: cannot run the engine %s: %s\n", engine, std::strerror(errno));
  return 127;
}
