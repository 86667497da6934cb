#include "passageMesh/core/HeapRetention.hpp"

#include <cstdlib>  // defines __GLIBC__ where the C library is glibc
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace passageMesh {

void retainFreedHeapMemory() {
#if defined(__GLIBC__)
  // Setting either value turns off glibc's own adjustment of both, so both are set; 32 MiB
  // is the largest mmap threshold glibc accepts on a 64-bit machine.
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 256 * 1024 * 1024);
#endif
}

}  // namespace passageMesh
