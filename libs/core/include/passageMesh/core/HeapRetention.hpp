#pragma once
// Memory a process frees stays with it for reuse, rather than going back to the kernel at
// once. Why: a learner step of policyTrain (LibTorch tensors) or a mesh allocates and frees
// megabytes over and over; by default glibc returns the freed top of its heap to the kernel
// (above 128 KiB, a threshold it raises only as far as 32 MiB) and serves large blocks by
// mmap, so the next step writes to fresh pages, each a page fault the kernel must zero.
// In policyTrain that was about 1.3 million faults per 1000 episodes and a third of its
// CPU time early in a run (docs/benchmarks.md "Freed memory kept for reuse"). Results do not change: only where the
// bytes come from (the meshes' digest and the trained weights are bit for bit the same).

namespace passageMesh {

// Keeps up to 256 MiB of freed heap for reuse and serves blocks up to 32 MiB from the
// heap (glibc's mallopt; elsewhere nothing). Every utility calls it (runUtility); a
// program that repeats work and does not go through runUtility calls it first.
void retainFreedHeapMemory();

}  // namespace passageMesh
