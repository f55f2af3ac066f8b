// First touches of the heap's fresh pages, taken ahead of the program on an idle core.
#pragma once

namespace hlr::runtime {

// Call once at start, after keep_freed_memory(). The kernel zeroes a page of fresh memory when it is
// first touched, on the thread that touches it: on the 2-core machines measured, 0.65 ms a megabyte, and
// much of it fell on the one thread that imports a mesh while the other core had nothing to do (fandisk:
// 12 of a 48 ms run). A background thread at the lowest priority keeps the few megabytes just past the
// heap's highest use faulted in (MADV_POPULATE_WRITE, which leaves what pages hold as it is), so the
// program's next allocations find their pages ready; when the cores are busy it gets next to no time.
// Peak memory grows by at most that margin. A no-op where the C library is not glibc, under
// AddressSanitizer (its own allocator), or where the kernel cannot populate pages (before Linux 5.14).
void warm_heap_ahead();

}  // namespace hlr::runtime
