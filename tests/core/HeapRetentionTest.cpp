#include "passageMesh/core/HeapRetention.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <array>
#include <cstdlib>

namespace passageMesh {
namespace {

long minorPageFaults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

constexpr std::size_t blockBytes = 256u << 10;
constexpr int blocks = 40;

// Allocates 40 blocks of 256 KiB (10 MiB), writes one byte in each of their pages, frees
// them all, as a learner step does with its tensors.
void oneStep() {
  std::array<volatile char*, blocks> block{};
  for (auto& b : block) {
    b = static_cast<volatile char*>(std::malloc(blockBytes));
    ASSERT_NE(b, nullptr);
    for (std::size_t i = 0; i < blockBytes; i += 4096) b[i] = static_cast<char>(i);
  }
  for (auto& b : block) std::free(const_cast<char*>(b));
}

// By default glibc maps the first blocks, raises its thresholds to their size and then
// gives the freed 10 MiB back at the end of each step (it is more than twice the largest
// block), so every step faults its 2560 pages in again. Retained, only the first does.
TEST(HeapRetention, AStepThatFreesWhatItAllocatedReusesItsPagesInTheNext) {
#if defined(__GLIBC__)
  retainFreedHeapMemory();
  const long pagesPerStep = static_cast<long>(blocks * blockBytes / 4096);
  oneStep();
  oneStep();
  const long before = minorPageFaults();
  for (int step = 0; step < 10; ++step) oneStep();
  EXPECT_LT(minorPageFaults() - before, pagesPerStep);
#else
  GTEST_SKIP() << "the allocator's thresholds are glibc's";
#endif
}

}  // namespace
}  // namespace passageMesh
