// The multigrid's coarse grid of an O-block (GridCoarsening.hpp): which fine nodes it
// keeps, and the bilinear interpolation of a coarse displacement back to the fine grid.
#include "passageMesh/mesh/GridCoarsening.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "AnnulusTestData.hpp"

using namespace passageMesh;

namespace {

// A displacement affine in the fine indices (i, j), written onto the coarse nodes.
double affineX(int i, int j) { return 0.1 + 0.01 * i + 0.02 * j; }
double affineY(int i, int j) { return -0.05 + 0.003 * i - 0.03 * j; }

}  // namespace

TEST(GridCoarsening, KeepsEveryOtherNodeAndEveryFixedRow) {
  for (const int n : {64, 63}) {
    const StructuredBlock fine = testData::annulus(n, 17, 0.1);
    const MovingRows rows{2, 1};
    const Coarsening c = coarseningOf(fine, rows, 16, 4);
    ASSERT_TRUE(c.i && c.j);
    const StructuredBlock coarse = coarseBlock(fine, c);
    EXPECT_EQ(coarse.ni - 1, (n + 1) / 2);
    // The fixed rows (0, 1 below, 16 above) are rows of the coarse grid.
    for (const int fixed : {0, 1, 16})
      EXPECT_NE(std::find(c.fineRowOf.begin(), c.fineRowOf.end(), fixed), c.fineRowOf.end()) << fixed;
    for (int J = 0; J < coarse.nj; ++J)
      for (int I = 0; I < coarse.ni - 1; ++I) {
        const int fj = c.fineRowOf[static_cast<std::size_t>(J)];
        EXPECT_EQ(coarse.xAt(I, J), fine.xAt(c.fineI(I), fj));
        EXPECT_EQ(coarse.yAt(I, J), fine.yAt(c.fineI(I), fj));
      }
  }
}

TEST(GridCoarsening, InterpolatedDisplacementIsBilinearInTheFineIndices) {
  for (const int n : {64, 63}) {
    const StructuredBlock fine = testData::annulus(n, 17, 0.1);
    const MovingRows rows{2, 1};
    const Coarsening c = coarseningOf(fine, rows, 16, 4);
    const StructuredBlock before = coarseBlock(fine, c);
    StructuredBlock after = before;
    for (int J = 0; J < after.nj; ++J)
      for (int I = 0; I < after.ni; ++I) {
        const int fi = c.fineI(I), fj = c.fineRowOf[static_cast<std::size_t>(J)];
        after.xAt(I, J) += affineX(fi, fj);
        after.yAt(I, J) += affineY(fi, fj);
      }
    std::vector<double> dx, dy;
    interpolateDisplacement(before, after, c, fine, rows, dx, dy);
    ASSERT_EQ(dx.size(), fine.x.size());
    for (int j = 0; j < fine.nj; ++j)
      for (int i = 0; i < fine.ni; ++i) {
        const auto k = static_cast<std::size_t>(i + fine.ni * j);
        if (j < rows.first() || j > rows.last(fine)) {  // fixed rows do not move
          EXPECT_EQ(dx[k], 0.0);
          EXPECT_EQ(dy[k], 0.0);
        } else if (i == n) {  // the seam: the same node as i = 0
          EXPECT_EQ(dx[k], dx[static_cast<std::size_t>(fine.ni * j)]);
          EXPECT_EQ(dy[k], dy[static_cast<std::size_t>(fine.ni * j)]);
        } else if (i < n - 2) {  // away from the wrap, where the affine field is continuous
          EXPECT_NEAR(dx[k], affineX(i, j), 1e-14) << i << " " << j;
          EXPECT_NEAR(dy[k], affineY(i, j), 1e-14) << i << " " << j;
        }
      }
    // A displacement that depends on the row alone is continuous across the seam: exact at
    // every node, the last intervals of the loop (an odd loop's single one) included.
    after = before;
    for (int J = 0; J < after.nj; ++J)
      for (int I = 0; I < after.ni; ++I) after.yAt(I, J) += affineY(0, c.fineRowOf[static_cast<std::size_t>(J)]);
    interpolateDisplacement(before, after, c, fine, rows, dx, dy);
    for (int j = rows.first(); j <= rows.last(fine); ++j)
      for (int i = 0; i < fine.ni; ++i) {
        const auto k = static_cast<std::size_t>(i + fine.ni * j);
        EXPECT_EQ(dx[k], 0.0) << i << " " << j;
        EXPECT_NEAR(dy[k], affineY(0, j), 1e-14) << i << " " << j;
      }
  }
}
