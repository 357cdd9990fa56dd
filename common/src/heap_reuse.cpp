// Keeping freed memory for reuse; see heap_reuse.hpp.
#include "isosid/common/heap_reuse.hpp"

#include <atomic>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace isosid::common {
namespace {
std::atomic<int> g_scopes{0};
}  // namespace

HeapReuse::HeapReuse() {
#if defined(__GLIBC__)
  if (g_scopes++ > 0) return;
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, -1);  // read as the largest size: never give the heap's top back
#endif
}

HeapReuse::~HeapReuse() {
#if defined(__GLIBC__)
  if (--g_scopes > 0) return;
  mallopt(M_MMAP_MAX, 65536);               // glibc's default
  mallopt(M_TRIM_THRESHOLD, 64 << 20);      // where glibc's own adjustment tops out
  malloc_trim(0);
#endif
}

double freed_bytes_held() {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || __GLIBC_MINOR__ >= 33)
  return double(mallinfo2().fordblks);
#else
  return 0.0;
#endif
}

}  // namespace isosid::common
