// Giving freed heap memory back to the operating system after a burst of large temporary allocations.
//
// A pose-graph solve allocates tens of MB for a moment (the normal equations' triplets, CHOLMOD's
// factor) and frees them. glibc keeps freed heap pages resident: after it frees one large block it
// raises its mmap threshold, so the next blocks of that size come from the heap, and a heap page is
// given back only when the free space sits at the heap's top. A long-running mapper's resident memory
// then holds the peak of its largest solve so far (the nodelet soak, 2026-12-08: +75 MB in an hour of
// which the live heap was 67 MB at its peak and ~40 MB between solves; docs/results/nodelet_soak.md).
#pragma once

namespace doorplate_localization {

// Returns the heap's wholly free pages to the system (glibc's malloc_trim: every arena, free pages in the
// middle of a heap too). Returns true if memory was given back; false if none was or the C library cannot
// (not glibc, or a sanitizer's allocator, which keeps its own). Costs a walk over the free lists:
// milliseconds for a heap of 100 MB; call it after a large operation, not per message.
bool ReturnFreedMemoryToSystem();

}  // namespace doorplate_localization
