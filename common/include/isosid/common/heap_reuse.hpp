// Keeping freed memory for the program's next allocations, within a stretch of work. glibc's
// malloc serves each request above its mmap threshold (128 KiB, rising to 32 MiB) with fresh
// pages from the kernel and returns them at free, so a solver that allocates and frees large
// dense blocks in a loop (Krylov blocks, right-hand sides, sparse products) pays a page fault
// and a zeroed page for every 4 KiB of every block, each time. Serving them from the heap, and
// keeping what is freed there, lets later blocks reuse the same pages. The price is memory: the
// heap holds the freed blocks, and one that does not fit a hole grows it. So the reuse is
// scoped: a million-DOF assembly under it grew past the machine's 24 GB where it had fitted.
#pragma once

namespace isosid::common {

/// While one is alive, this process's large allocations come from the heap and freed memory
/// stays in it for reuse (glibc's M_MMAP_MAX = 0, no trimming). When the last one ends, large
/// allocations are mapped again and the heap gives back the pages it holds free (malloc_trim).
/// Without glibc, or under a sanitizer's allocator, it changes nothing.
class HeapReuse {
public:
  HeapReuse();
  ~HeapReuse();
  HeapReuse(const HeapReuse&) = delete;
  HeapReuse& operator=(const HeapReuse&) = delete;
};

/// Bytes that this process's allocator holds free for reuse: memory it has from the kernel but
/// will hand out again before asking for more, so a memory check may count it as available.
double freed_bytes_held();

}  // namespace isosid::common
