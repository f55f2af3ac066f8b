// How the process's allocator treats memory that is freed: kept for reuse, not handed back to the kernel.
#pragma once

namespace hlr::runtime {

// Call once at start, before threads exist. glibc maps each block of 128 KiB or more (a threshold that
// only creeps up) on its own and unmaps it when freed, and trims the heap's top: every frame's candidate
// lists, grids and pen graphs then come back as fresh pages, and first touches of fresh pages are what a
// frame spends most of its system time on (the 100k-face turntable: 0.9 of 4.7 s). Blocks up to 32 MiB
// (glibc's largest threshold) now come from the heap and freed memory stays there; peak memory grows by
// about a tenth. A no-op where the C library is not glibc.
void keep_freed_memory();

}  // namespace hlr::runtime
