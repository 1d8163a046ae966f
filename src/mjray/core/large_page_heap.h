#pragma once
/// The heap on large pages. A render's description, its flat world and its images are tens of
/// MiB allocated piece by piece, mostly on one thread before any ray is traced; every 4 KiB
/// page costs a fault when first written (several microseconds under a hypervisor), about a
/// quarter of a small render's wall time. On Linux, whose transparent huge pages go to memory
/// that asks for them, this asks for the heap's next `bytes`.

#include <cstddef>

namespace mjray {

/// Whether this build replaces the C library's allocator with AddressSanitizer's, which
/// serves no block from the heap that the advice covers.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitizerAllocator = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitizerAllocator = true;
#else
constexpr bool kSanitizerAllocator = false;
#endif
#else
constexpr bool kSanitizerAllocator = false;
#endif

/// Extends the heap by `bytes` at once (at most an eighth of a limit on address space) and
/// advises 2 MiB pages for it; allocations below 32 MiB come from the heap from then on. Call
/// once, first thing in main(), before any thread starts. Does nothing where the system or
/// the C library offers no such advice, and under AddressSanitizer.
void back_heap_with_large_pages(size_t bytes);

}  // namespace mjray
