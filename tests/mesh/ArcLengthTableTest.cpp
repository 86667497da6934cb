// ArcLengthTable places nodes by length (the blade sides' wall nodes, the outer loop's along
// the periodic boundary): the parameter at a length is interpolated linearly between the
// samples, and clamped.
#include "passageMesh/mesh/ArcLengthTable.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace passageMesh;

TEST(ArcLengthTable, ParameterAtALengthInterpolatesBetweenSamplesAndClampsAtTheEnds) {
  // Three samples on the x axis: lengths 0, 1, 3 at parameters 0, 0.1, 1.
  const ArcLengthTable table({0, 0.1, 1}, {{0, 0}, {1, 0}, {3, 0}});
  EXPECT_DOUBLE_EQ(table.length(), 3);
  EXPECT_DOUBLE_EQ(table.parameterAt(0.5), 0.05);
  EXPECT_DOUBLE_EQ(table.parameterAt(1), 0.1);
  EXPECT_DOUBLE_EQ(table.parameterAt(2), 0.55);
  EXPECT_EQ(table.parameterAt(-1), 0);
  EXPECT_EQ(table.parameterAt(4), 1);
  // A diagonal polygon: lengths are Euclidean.
  const ArcLengthTable diagonal({0, 1}, {{0, 0}, {3, 4}});
  EXPECT_DOUBLE_EQ(diagonal.length(), 5);
  EXPECT_DOUBLE_EQ(diagonal.parameterAt(2.5), 0.5);
}

TEST(ArcLengthTable, RefusesMismatchedOrTooFewSamples) {
  EXPECT_THROW(ArcLengthTable({0, 1}, {{0, 0}}), std::invalid_argument);
  EXPECT_THROW(ArcLengthTable({0}, {{0, 0}}), std::invalid_argument);
}
