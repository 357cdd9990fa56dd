// Freed memory kept in the heap: a block above glibc's mmap threshold, once freed, is held for
// reuse and counted by freed_bytes_held (so the preprocessor's memory checks count it as
// available). Without keep_freed_memory_for_reuse glibc maps such a block and unmaps it at free,
// and the count would not grow.
#include "isosid/common/heap_reuse.hpp"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>

TEST_CASE("a freed large block stays in the heap, counted as held for reuse", "[heap]") {
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
  isosid::common::keep_freed_memory_for_reuse();
  const double before = isosid::common::freed_bytes_held();
  const std::size_t bytes = std::size_t(64) << 20;  // above glibc's largest mmap threshold (32 MiB)
  void* block = std::malloc(bytes);
  REQUIRE(block != nullptr);
  std::memset(block, 1, bytes);
  asm volatile("" : : "r"(block) : "memory");  // the allocation and its pages happen
  std::free(block);
  CHECK(isosid::common::freed_bytes_held() >= before + 0.99 * double(bytes));
#else
  WARN("not glibc's allocator (a sanitizer's or another libc's): nothing is kept");
#endif
}
