// Keeping freed memory for the program's next allocations. glibc's malloc serves each request
// above its mmap threshold (128 KiB, rising to 32 MiB) with fresh pages from the kernel and
// returns them at free, so a solver that allocates and frees large dense blocks in a loop
// (Krylov blocks, right-hand sides, sparse products) pays a page fault and a zeroed page for
// every 4 KiB of every block, each time. Serving them all from the heap, and keeping what is
// freed there, lets later blocks reuse the same pages.
#pragma once

namespace isosid::common {

/// From now on, this process's large allocations come from the heap and freed memory stays in
/// it for reuse (glibc's M_MMAP_MAX = 0, M_TRIM_THRESHOLD beyond any heap). Call first thing in
/// main; without glibc, or under a sanitizer's allocator, it changes nothing.
void keep_freed_memory_for_reuse();

/// Bytes that this process's allocator holds free for reuse: memory it has from the kernel but
/// will hand out again before asking for more, so a memory check may count it as available.
double freed_bytes_held();

}  // namespace isosid::common
