// Keeping freed memory for reuse; see heap_reuse.hpp.
#include "isosid/common/heap_reuse.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace isosid::common {

void keep_freed_memory_for_reuse() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, -1);  // read as the largest size: never give the heap's top back
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
