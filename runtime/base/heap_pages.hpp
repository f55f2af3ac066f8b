// Which pages the heap goes on: transparent huge pages, except on a virtual machine whose host takes back
// the memory its guest frees. Header only, on the C library alone: the launcher (runtime/cli/launcher.cpp)
// links nothing else.
//
// Why the exception: a virtio balloon with free page reporting hands blocks of free memory of 2 MiB and
// more back to the host within seconds. A huge page is such a block, so a run that starts a few seconds
// after the last one gets its huge pages back from the host, and there the first touch cost 2.4 ms a
// megabyte against 0.12 for a huge page just freed and 0.35 for small pages (bench/README.md, stop 48).
// Measured 22 s apart, the bunny ran in 154 ms on huge pages against 123 on small ones, and the
// 10⁶-triangle torus in 1.9 s against 1.2 s. Back to back, huge pages were 2–6 % faster.
#pragma once

#include <dirent.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace hlr::runtime {

inline constexpr const char* kVirtioDevices = "/sys/bus/virtio/devices";
// The glibc tunable, and its two settings.
inline constexpr const char* kHugetlbTunable = "glibc.malloc.hugetlb";
inline constexpr const char* kHugePages = "glibc.malloc.hugetlb=1";
inline constexpr const char* kSmallPages = "glibc.malloc.hugetlb=0";

// Whether a virtio balloon among `devices` (a folder per device, as in sysfs: `device` holds the device
// id, `features` one '0' or '1' per feature bit) reports free pages to the host (VIRTIO_BALLOON_F_REPORTING,
// bit 5). Anything unreadable counts as no.
inline bool host_takes_back_free_memory(const char* devices = kVirtioDevices) {
  constexpr long kBalloon = 5;           // virtio device id of a memory balloon
  constexpr std::size_t kReporting = 5;  // its feature bit for free page reporting
  DIR* folder = ::opendir(devices);
  if (folder == nullptr) return false;
  bool reporting = false;
  char path[512];
  char text[512];
  auto read_line = [&](const char* device, const char* file) {
    const int n = std::snprintf(path, sizeof path, "%s/%s/%s", devices, device, file);
    if (n <= 0 || static_cast<std::size_t>(n) >= sizeof path) return false;
    std::FILE* f = std::fopen(path, "r");
    if (f == nullptr) return false;
    const bool read = std::fgets(text, sizeof text, f) != nullptr;
    std::fclose(f);
    return read;
  };
  while (const dirent* entry = ::readdir(folder)) {
    if (entry->d_name[0] == '.' || !read_line(entry->d_name, "device")) continue;
    char* end = nullptr;
    if (std::strtol(text, &end, 0) != kBalloon || end == text) continue;
    if (read_line(entry->d_name, "features") && std::strlen(text) > kReporting && text[kReporting] == '1') {
      reporting = true;
      break;
    }
  }
  ::closedir(folder);
  return reporting;
}

// The glibc tunable to start the engine with: huge pages, or small ones where the host takes back freed
// memory.
inline const char* heap_page_tunable(const char* devices = kVirtioDevices) {
  return host_takes_back_free_memory(devices) ? kSmallPages : kHugePages;
}

}  // namespace hlr::runtime
