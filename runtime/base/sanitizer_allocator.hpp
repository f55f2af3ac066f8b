// HLR_OWN_ALLOCATOR: defined when AddressSanitizer replaces the C library's allocator, so that glibc's
// tunables and heap (allocator_policy.*, heap_warmer.*) mean nothing.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define HLR_OWN_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HLR_OWN_ALLOCATOR 1
#endif
#endif
