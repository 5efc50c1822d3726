// reuse_freed_memory: glibc's mallopt, set once per process.
#include "envcrust/heap.h"

#include <climits>  // also defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace envcrust::io {

void reuse_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);              // no block of its own mapping: all from the heap
  mallopt(M_TRIM_THRESHOLD, INT_MAX);  // and the heap's free top is not given back
#endif
}

}  // namespace envcrust::io
