// redistributeAlongLines on an annulus (AnnulusTestData.hpp: radial lines, concentric
// loops, rows evenly spaced) where every
// answer is known: nodes on the radial lines, the first row exactly firstSpacing out, the
// last row the outer circle, the last spacing 90 % of the way from the plain clustering's
// to the outer loop's node spacing.
#include "passageMesh/mesh/LineRedistribution.hpp"
#include "passageMesh/mesh/Stretching.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "AnnulusTestData.hpp"

using namespace passageMesh;

using testData::annulus;
using testData::innerRadius;
using testData::outerRadius;

TEST(LineRedistribution, NodesStayOnTheLinesWithExactEnds) {
  const int n = 64;
  const StructuredBlock lines = annulus(n, 9);
  StructuredBlock target = annulus(n, 40);
  const double first = 1e-3;
  std::vector<Eigen::Vector2d> normals;
  for (int i = 0; i < n; ++i) normals.emplace_back(Eigen::Vector2d(lines.xAt(i, 0), lines.yAt(i, 0)));
  redistributeAlongLines(lines, target, first, normals);
  const double loopSpacing = 2 * outerRadius * std::sin(std::numbers::pi / n);  // outer chord
  const auto plain = wallClusteredDistances(target.nj, outerRadius - innerRadius, first);
  const double plainLast = plain[target.nj - 1] - plain[target.nj - 2];
  for (int i = 0; i <= n; ++i) {
    const double a = std::atan2(lines.yAt(i, 0), lines.xAt(i, 0));
    double previous = innerRadius;
    for (int j = 0; j < target.nj; ++j) {
      const double r = std::hypot(target.xAt(i, j), target.yAt(i, j));
      EXPECT_NEAR(std::atan2(target.yAt(i, j), target.xAt(i, j)), a, 1e-12) << i << " " << j;
      if (j > 0) {
        ASSERT_GT(r, previous) << i << " " << j;
      }
      previous = r;
    }
    EXPECT_NEAR(std::hypot(target.xAt(i, 1), target.yAt(i, 1)) - innerRadius, first, 1e-14) << i;
    EXPECT_NEAR(std::hypot(target.xAt(i, target.nj - 1), target.yAt(i, target.nj - 1)), outerRadius, 1e-14);
    const double last = outerRadius - std::hypot(target.xAt(i, target.nj - 2), target.yAt(i, target.nj - 2));
    EXPECT_NEAR(last, plainLast + 0.9 * (loopSpacing - plainLast), 1e-3 * loopSpacing) << i;
  }
  EXPECT_EQ(target.xAt(n, 5), target.xAt(0, 5));
}

TEST(LineRedistribution, MismatchedBlocksAreRefused) {
  const StructuredBlock lines = annulus(16, 5);
  StructuredBlock target = annulus(17, 20);
  EXPECT_THROW(redistributeAlongLines(lines, target, 1e-3), std::invalid_argument);
}

// HohMesh's wall-angle limit: row 1 alone along the given directions, firstSpacing out;
// every other row where it is without them.
TEST(LineRedistribution, TheFirstRowAloneFollowsItsOwnDirections) {
  const int n = 32;
  const StructuredBlock lines = annulus(n, 9);
  StructuredBlock plain = annulus(n, 30), turned = annulus(n, 30);
  const double first = 1e-3, tilt = 0.1;  // [rad]
  std::vector<Eigen::Vector2d> normals, firstRow;
  for (int i = 0; i < n; ++i) {
    const double a = std::atan2(lines.yAt(i, 0), lines.xAt(i, 0));
    normals.emplace_back(std::cos(a), std::sin(a));
    firstRow.emplace_back(std::cos(a + tilt), std::sin(a + tilt));
  }
  redistributeAlongLines(lines, plain, first, normals);
  redistributeAlongLines(lines, turned, first, normals, 3.0, firstRow);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d wall(lines.xAt(i, 0), lines.yAt(i, 0));
    const Eigen::Vector2d expected = wall + first * firstRow[static_cast<std::size_t>(i)];
    EXPECT_NEAR(turned.xAt(i, 1), expected.x(), 1e-15) << i;
    EXPECT_NEAR(turned.yAt(i, 1), expected.y(), 1e-15) << i;
    for (int j = 0; j < turned.nj; ++j) {
      if (j == 1) continue;
      EXPECT_EQ(turned.xAt(i, j), plain.xAt(i, j)) << i << " " << j;
      EXPECT_EQ(turned.yAt(i, j), plain.yAt(i, j)) << i << " " << j;
    }
  }
  firstRow.pop_back();
  EXPECT_THROW(redistributeAlongLines(lines, turned, first, normals, 3.0, firstRow), std::invalid_argument);
}
