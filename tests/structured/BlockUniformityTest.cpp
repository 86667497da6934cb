#include "passageMesh/structured/BlockUniformity.hpp"

#include <gtest/gtest.h>

#include "StructuredTestData.hpp"

using namespace passageMesh;
using testData::uniformBlock;

TEST(BlockUniformity, UniformBlocksGiveZero) {
  EXPECT_NEAR(blockNonUniformity(uniformBlock("H", 5, 4, 0.25, 0.5)), 0, 1e-13);
  // Parallelograms.
  EXPECT_NEAR(blockNonUniformity(uniformBlock("H", 5, 4, 0.25, 0.5, 0.3)), 0, 1e-13);
}

TEST(BlockUniformity, GivesTheLargestRelativeEdgeDeviation) {
  StructuredBlock b = uniformBlock("H", 3, 2);
  b.xAt(2, 0) = 3;  // i-edges on row 0: 1 and 2; the i-edges' mean is (1 + 2 + 1 + 1) / 4
  EXPECT_NEAR(blockNonUniformity(b), 2 / 1.25 - 1, 1e-12);
}
