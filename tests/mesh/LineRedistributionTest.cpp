// redistributeAlongLines on an annulus (radial lines, concentric loops) where every
// answer is known: nodes on the radial lines, the first row exactly firstSpacing out, the
// last row the outer circle, the last spacing 90 % of the way from the plain clustering's
// to the outer loop's node spacing.
#include "passageMesh/mesh/LineRedistribution.hpp"
#include "passageMesh/mesh/Stretching.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace passageMesh;

namespace {

// ni = n + 1 (seam repeated), rows evenly spaced from radius 1 to 3, i clockwise (the
// O-block's orientation: right-handed with j outwards).
StructuredBlock evenAnnulus(int n, int nj) {
  StructuredBlock b;
  b.name = "OBlock";
  b.ni = n + 1;
  b.nj = nj;
  b.x.resize(static_cast<std::size_t>(b.ni) * nj);
  b.y.resize(b.x.size());
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i <= n; ++i) {
      const double r = 1 + 2.0 * j / (nj - 1), a = -2 * std::numbers::pi * (i % n) / n;
      b.xAt(i, j) = r * std::cos(a);
      b.yAt(i, j) = r * std::sin(a);
    }
  return b;
}

}  // namespace

TEST(LineRedistribution, NodesStayOnTheLinesWithExactEnds) {
  const int n = 64;
  const StructuredBlock lines = evenAnnulus(n, 9);
  StructuredBlock target = evenAnnulus(n, 40);
  const double first = 1e-3;
  std::vector<Eigen::Vector2d> normals;
  for (int i = 0; i < n; ++i) normals.emplace_back(Eigen::Vector2d(lines.xAt(i, 0), lines.yAt(i, 0)));
  redistributeAlongLines(lines, target, first, normals);
  const double loopSpacing = 2 * 3 * std::sin(std::numbers::pi / n);  // chord of the outer circle
  const auto plain = wallClusteredDistances(target.nj, 2.0, first);
  const double plainLast = plain[target.nj - 1] - plain[target.nj - 2];
  for (int i = 0; i <= n; ++i) {
    const double a = std::atan2(lines.yAt(i, 0), lines.xAt(i, 0));
    double previous = 1;
    for (int j = 0; j < target.nj; ++j) {
      const double r = std::hypot(target.xAt(i, j), target.yAt(i, j));
      EXPECT_NEAR(std::atan2(target.yAt(i, j), target.xAt(i, j)), a, 1e-12) << i << " " << j;
      if (j > 0) ASSERT_GT(r, previous) << i << " " << j;
      previous = r;
    }
    EXPECT_NEAR(std::hypot(target.xAt(i, 1), target.yAt(i, 1)) - 1, first, 1e-14) << i;
    EXPECT_NEAR(std::hypot(target.xAt(i, target.nj - 1), target.yAt(i, target.nj - 1)), 3, 1e-14);
    const double last = 3 - std::hypot(target.xAt(i, target.nj - 2), target.yAt(i, target.nj - 2));
    EXPECT_NEAR(last, plainLast + 0.9 * (loopSpacing - plainLast), 1e-3 * loopSpacing) << i;
  }
  EXPECT_EQ(target.xAt(n, 5), target.xAt(0, 5));
}

TEST(LineRedistribution, MismatchedBlocksAreRefused) {
  const StructuredBlock lines = evenAnnulus(16, 5);
  StructuredBlock target = evenAnnulus(17, 20);
  EXPECT_THROW(redistributeAlongLines(lines, target, 1e-3), std::invalid_argument);
}
