#include "passageMesh/structured/CellValidity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "StructuredTestData.hpp"

using namespace passageMesh;
using testData::uniformBlock;

TEST(CellValidity, ConvexCounterclockwiseCellsAreValid) {
  EXPECT_TRUE(cellIsValid({0, 1, 1, 0}, {0, 0, 1, 1}));
  EXPECT_TRUE(cellIsValid({0, 2, 1.5, 0.2}, {0, 0.1, 1, 0.8}));  // a general quadrilateral
}

TEST(CellValidity, FoldedInvertedDegenerateAndNonConvexCellsAreNot) {
  EXPECT_FALSE(cellIsValid({0, 1, 0, 1}, {0, 0, 1, 1}));      // bow tie
  EXPECT_FALSE(cellIsValid({0, 0, 1, 1}, {0, 1, 1, 0}));      // clockwise: inverted
  EXPECT_FALSE(cellIsValid({0, 1, 2, 0}, {0, 0, 0, 1}));      // straight corner: degenerate
  EXPECT_FALSE(cellIsValid({0, 1, 0.2, 0}, {0, 0, 0.2, 1}));  // a reflex corner
  EXPECT_FALSE(cellIsValid({0, 1, 1, 0}, {0, 0, 0, 0}));      // zero area
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(cellIsValid({0, 1, nan, 0}, {0, 0, 1, 1}));
}

TEST(CellValidity, FindsTheFirstInvalidCellByBlockRowAndColumn) {
  StructuredMesh mesh;
  mesh.blocks = {uniformBlock("B", 4, 3), uniformBlock("C", 3, 3)};
  EXPECT_EQ(findInvalidCell(mesh), "");
  mesh.blocks[1].xAt(2, 1) = -1;  // folds cells (1, 0) and (1, 1) of block C
  EXPECT_EQ(findInvalidCell(mesh), "C cell (1, 0) is folded or degenerate");
  mesh.blocks[0].yAt(3, 2) = 0.5;  // pulls a corner of cell (2, 1) of block B across it
  mesh.blocks[0].xAt(3, 2) = 1.5;
  EXPECT_EQ(findInvalidCell(mesh), "B cell (2, 1) is folded or degenerate");
  // One block alone: the same message.
  EXPECT_EQ(findInvalidCell(mesh.blocks[1]), "C cell (1, 0) is folded or degenerate");
  EXPECT_EQ(findInvalidCell(uniformBlock("D", 3, 3)), "");
}

TEST(CellValidity, CellsValidFromSkipsTheRowsBelow) {
  StructuredBlock block = uniformBlock("B", 4, 4);
  EXPECT_TRUE(cellsValidFrom(block, 0));
  block.xAt(2, 1) = -1;  // folds the four cells around node (2, 1): rows 0 and 1
  EXPECT_FALSE(cellsValidFrom(block, 0));
  EXPECT_FALSE(cellsValidFrom(block, 1));
  EXPECT_TRUE(cellsValidFrom(block, 2));
  EXPECT_TRUE(cellsValidFrom(block, 3));   // no cell from the last row up
  EXPECT_FALSE(cellsValidFrom(block, -1)); // a row below 0 is row 0
}
