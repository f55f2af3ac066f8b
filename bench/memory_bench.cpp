// Peak memory and time of one render per process (a process's VmHWM only grows, so each scene needs its
// own). Not a Google Benchmark program: it has its own main.
//   memory_bench                 run the standard list, one child process per scene, print a table
//   memory_bench city 100000     one scene in this process, print one row
// Columns: faces; scene generation time; render time; visible segments; heap held by the built scene; the
// render's own peak heap (operator new is counted here: peak during the render minus the heap before it —
// RSS cannot show this, as the render reuses pages the scene builder freed); that per face; and the
// process's VmHWM, the whole peak.
#include <malloc.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "bench/bench_scenes.hpp"
#include "core/hlr/render_frame.hpp"

extern char** environ;

// ---- heap accounting: every operator new/delete of the process goes through here ----------------------
namespace {
std::atomic<long long> g_heap{0}, g_heap_peak{0};

void* counted(void* p) {
  if (!p) throw std::bad_alloc();
  const long long now = g_heap += static_cast<long long>(malloc_usable_size(p));
  for (long long peak = g_heap_peak; now > peak && !g_heap_peak.compare_exchange_weak(peak, now);) {
  }
  return p;
}
void uncounted(void* p) noexcept {
  if (!p) return;
  g_heap -= static_cast<long long>(malloc_usable_size(p));
  std::free(p);
}
}  // namespace

void* operator new(std::size_t n) { return counted(std::malloc(n ? n : 1)); }
void* operator new[](std::size_t n) { return counted(std::malloc(n ? n : 1)); }
void* operator new(std::size_t n, std::align_val_t a) {
  const auto al = static_cast<std::size_t>(a);
  return counted(std::aligned_alloc(al, (n + al - 1) / al * al));
}
void* operator new[](std::size_t n, std::align_val_t a) { return operator new(n, a); }
void operator delete(void* p) noexcept { uncounted(p); }
void operator delete[](void* p) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::size_t) noexcept { uncounted(p); }
void operator delete(void* p, std::align_val_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::align_val_t) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { uncounted(p); }

namespace {

void print_header() {
  std::printf("| scene | generator | faces | build s | render s | segments | scene heap MB | render peak heap MB | "
              "render bytes/face | process VmHWM MB |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::fflush(stdout);  // before the children write their rows
}

int run_one(const std::string& kind, std::size_t faces) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const hlr::bench::BenchScene s = hlr::bench::make_scene(kind, faces);
  const auto t1 = clock::now();
  const long long heap_scene = g_heap;
  g_heap_peak = heap_scene;
  hlr::HlrOptions options;
  options.threads = 1;  // per-core numbers; each extra thread adds only its small scratch
  const hlr::FrameResult r = hlr::render_frame(s.scene, s.camera, options);
  const auto t2 = clock::now();
  const double render_peak = static_cast<double>(g_heap_peak - heap_scene);
  constexpr double kMB = 1 << 20;
  std::printf("| %s | %s | %zu | %.2f | %.3f | %zu | %.1f | %.1f | %.0f | %.1f |\n", kind.c_str(), s.detail.c_str(),
              s.faces, std::chrono::duration<double>(t1 - t0).count(), std::chrono::duration<double>(t2 - t1).count(),
              r.stats.visible_segments, static_cast<double>(heap_scene) / kMB, render_peak / kMB,
              render_peak / static_cast<double>(s.faces), static_cast<double>(hlr::bench::peak_rss_bytes()) / kMB);
  std::fflush(stdout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3) return run_one(argv[1], std::strtoul(argv[2], nullptr, 10));
  if (argc != 1) {
    std::fprintf(stderr, "usage: %s [city|sphere|torus|mesh FACES]\n", argv[0]);
    return 2;
  }
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"city", "100"},      {"city", "1000"},     {"city", "10000"},   {"city", "100000"}, {"city", "1000000"},
      {"sphere", "100"},    {"sphere", "10000"},  {"sphere", "1000000"}, {"torus", "100"},  {"torus", "10000"},
      {"torus", "1000000"}, {"mesh", "10000"},    {"mesh", "100000"}};
  print_header();
  for (const auto& [kind, faces] : runs) {
    // A fresh process per scene: its VmHWM starts from nothing.
    std::string self = "/proc/self/exe";
    char* args[] = {argv[0], const_cast<char*>(kind.c_str()), const_cast<char*>(faces.c_str()), nullptr};
    pid_t pid;
    if (posix_spawn(&pid, self.c_str(), nullptr, nullptr, args, environ) != 0) {
      std::perror("posix_spawn");
      return 1;
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) std::printf("| %s | %s | failed (status %d) |\n", kind.c_str(), faces.c_str(), status);
  }
  return 0;
}
