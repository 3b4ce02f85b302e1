#include "util/heap_reuse.hpp"

#include <cstdlib>  // defines __GLIBC__ where the C library is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace mpr {

void keepFreedHeapMemory() {
#if defined(__GLIBC__)
  // Setting either fixes it (glibc's dynamic threshold stops moving).
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 512 * 1024 * 1024);
#endif
}

}  // namespace mpr
