// How the process's allocator treats memory that is freed: kept for reuse, not handed back to the kernel.
#pragma once

namespace hlr::runtime {

// Call once at start, before threads exist. glibc maps each block of 128 KiB or more (a threshold that
// only creeps up) on its own and unmaps it when freed, and trims the heap's top: every frame's candidate
// lists, grids and pen graphs then come back as fresh pages, and first touches of fresh pages are what a
// frame spends most of its system time on (the 100k-face turntable: 0.9 of 4.7 s). Blocks up to 32 MiB
// (glibc's largest threshold) now come from the heap and freed memory stays there; peak memory grows by
// about a tenth. All threads share one arena, so that memory freed on one is reused on another. A no-op
// where the C library is not glibc.
void keep_freed_memory();

// Call first thing in main(). Puts the heap on transparent huge pages: glibc reads its tunables only when
// a process starts, so the process executes itself again, once, with glibc.malloc.hugetlb=1 added to
// GLIBC_TUNABLES. A large script otherwise spends a quarter to two fifths of its time on first touches
// of fresh 4 KiB pages (the 64 000-box city's `check` 1.34 → 1.01 s, general code 1.26 → 0.71 s, a
// 10⁶-triangle import rendered 3.5 → 2.2 s; peak memory up to a tenth more: bench/README.md). Returns
// without effect when the setting is already there (the second start, or the user's own), under
// AddressSanitizer (its own allocator), where the C library is not glibc, on a virtual machine whose host
// takes back freed memory (heap_pages.hpp: small pages are faster there), or when /proc/self/exe cannot
// be executed. `hlrscript` (runtime/cli/launcher.cpp) starts the engine with the setting already there,
// so this only acts when the engine is run directly.
void heap_on_huge_pages(char** argv);

}  // namespace hlr::runtime
