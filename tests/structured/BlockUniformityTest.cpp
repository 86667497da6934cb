#include "passageMesh/structured/BlockUniformity.hpp"

#include <gtest/gtest.h>

using namespace passageMesh;

namespace {

// ni x nj nodes, spacing dx along i and dy along j, sheared by `shear` x per unit y.
StructuredBlock grid(int ni, int nj, double dx, double dy, double shear = 0) {
  StructuredBlock b;
  b.name = "H";
  b.ni = ni;
  b.nj = nj;
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i < ni; ++i) {
      b.x.push_back(i * dx + shear * j * dy);
      b.y.push_back(j * dy);
    }
  return b;
}

}  // namespace

TEST(BlockUniformity, UniformBlocksGiveZero) {
  EXPECT_NEAR(blockNonUniformity(grid(5, 4, 0.25, 0.5)), 0, 1e-15);
  EXPECT_NEAR(blockNonUniformity(grid(5, 4, 0.25, 0.5, 0.3)), 0, 1e-15);  // parallelograms
}

TEST(BlockUniformity, GivesTheLargestRelativeEdgeDeviation) {
  StructuredBlock b = grid(3, 2, 1, 1);
  b.xAt(2, 0) = 3;  // i-edges on row 0: 1 and 2; the i-edges' mean is (1 + 2 + 1 + 1) / 4
  EXPECT_NEAR(blockNonUniformity(b), 2 / 1.25 - 1, 1e-12);
}
