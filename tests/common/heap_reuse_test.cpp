// Freed memory kept in the heap while a HeapReuse lives: a block above glibc's mmap threshold,
// once freed, is held for reuse and counted by freed_bytes_held (so the preprocessor's memory
// checks count it as available). Without the scope glibc maps such a block and unmaps it at
// free, and the count does not grow; after the scope, that is so again.
#include "isosid/common/heap_reuse.hpp"
#include "isosid/format/isolated_probe.hpp"  // ISOSID_UNDER_ASAN

#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>

namespace {

/// Bytes that allocating, touching and freeing a 64 MiB block adds to the heap's free memory.
double held_after_a_large_block() {
  const double before = isosid::common::freed_bytes_held();
  const std::size_t bytes = std::size_t(64) << 20;  // above glibc's largest mmap threshold (32 MiB)
  void* block = std::malloc(bytes);
  REQUIRE(block != nullptr);
  std::memset(block, 1, bytes);
  asm volatile("" : : "r"(block) : "memory");  // the allocation and its pages happen
  std::free(block);
  return isosid::common::freed_bytes_held() - before;
}

}  // namespace

TEST_CASE("HeapReuse: a freed large block stays in the heap while the scope lives, and not after", "[heap]") {
#if defined(__GLIBC__) && !defined(ISOSID_UNDER_ASAN)
  const double block = double(std::size_t(64) << 20);
  {
    const isosid::common::HeapReuse reuse;
    CHECK(held_after_a_large_block() >= 0.99 * block);
  }
  CHECK(held_after_a_large_block() < 0.5 * block);
#else
  WARN("not glibc's allocator (a sanitizer's or another libc's): nothing is kept");
#endif
}
