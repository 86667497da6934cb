#include "passageMesh/mesh/Stretching.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace passageMesh;

TEST(Stretching, TanhStretchIsMonotoneWithFixedEnds) {
  for (double gs : {0.0, 0.5, 2.0, 5.0})
    for (double ge : {0.0, 1.0, 5.0}) {
      EXPECT_DOUBLE_EQ(tanhStretch(0.0, gs, ge), 0.0);
      EXPECT_DOUBLE_EQ(tanhStretch(1.0, gs, ge), 1.0);
      double last = 0;
      for (int k = 1; k <= 1000; ++k) {
        const double f = tanhStretch(k / 1000.0, gs, ge);
        ASSERT_GT(f, last) << gs << " " << ge << " " << k;
        last = f;
      }
    }
}

TEST(Stretching, ZeroStrengthIsUniformAndStrengthClustersItsOwnEnd) {
  for (double xi : {0.1, 0.37, 0.9}) EXPECT_NEAR(tanhStretch(xi, 0, 0), xi, 1e-15);
  const double h = 1e-3;
  auto firstSpacing = [&](double gs, double ge) { return tanhStretch(h, gs, ge); };
  auto lastSpacing = [&](double gs, double ge) { return 1 - tanhStretch(1 - h, gs, ge); };
  // Stronger start clustering: smaller first spacing, last spacing unchanged to O(h^2).
  EXPECT_LT(firstSpacing(3, 1), firstSpacing(1, 1));
  EXPECT_NEAR(lastSpacing(3, 1), lastSpacing(1, 1), 1e-5);
  EXPECT_LT(lastSpacing(1, 4), lastSpacing(1, 2));
}

TEST(Stretching, WallClusteringHitsTheFirstSpacingExactly) {
  for (int n : {20, 100, 300})
    for (double dn1 : {2e-5, 1.1e-4, 2e-3}) {
      if (dn1 >= 0.4 / (n - 1)) {  // would need stretching away from the wall
        EXPECT_THROW(wallClusteredDistances(n, 0.4, dn1), std::invalid_argument);
        continue;
      }
      const auto s = wallClusteredDistances(n, 0.4, dn1);
      ASSERT_EQ(s.size(), static_cast<std::size_t>(n));
      EXPECT_NEAR(s[1], dn1, 1e-12 * dn1) << n << " " << dn1;
      EXPECT_EQ(s.back(), 0.4);
      for (int j = 1; j < n; ++j) ASSERT_GT(s[j] - s[j - 1], 0.0);
      for (int j = 2; j < n; ++j) ASSERT_GE(s[j] - s[j - 1], s[j - 1] - s[j - 2] * (1 - 1e-12));
    }
  EXPECT_THROW(wallClusteredDistances(10, 1.0, 0.2), std::invalid_argument);  // would stretch away
  EXPECT_THROW(wallClusteredDistances(1, 1.0, 0.01), std::invalid_argument);
}

TEST(Stretching, LastSpacingIsMovedWhileTheFirstStaysExact) {
  const int n = 100;
  const double length = 0.5, first = 1e-4;
  const auto plain = wallClusteredDistances(n, length, first);
  for (double last : {0.011, 0.015, 0.03}) {  // the plain last spacing is 0.0118
    auto s = plain;
    moveLastSpacing(s, last);
    EXPECT_NEAR(s[1], first, 1e-15) << last;
    EXPECT_EQ(s[n - 1], length);
    EXPECT_NEAR(s[n - 1] - s[n - 2], last, 1e-12) << last;
    for (int j = 1; j < n; ++j) ASSERT_GT(s[j] - s[j - 1], 0.5 * (plain[j] - plain[j - 1])) << last << " " << j;
  }
  // A last spacing no such correction reaches is approached without folding: no spacing
  // falls below half the plain one (the binding one sits at half, to round-off).
  for (double unreachable : {1.0, 1e-7}) {
    auto far = plain;
    moveLastSpacing(far, unreachable);
    for (int j = 1; j < n; ++j)
      ASSERT_GE(far[j] - far[j - 1], 0.5 * (plain[j] - plain[j - 1]) * (1 - 1e-12)) << unreachable << " " << j;
    const double moved = far[n - 1] - far[n - 2], before = plain[n - 1] - plain[n - 2];
    EXPECT_TRUE(unreachable > before ? moved > before : moved < before) << unreachable;
  }
}

// The nodes move continuously with the wanted last spacing, also across the point where
// the correction starts to be clipped: Q along the meshing parameters has no jumps from
// here (docs/benchmarks.md, "Q along each meshing parameter").
TEST(Stretching, MovedDistancesAreContinuousInTheLastSpacing) {
  const int n = 40;
  const auto plain = wallClusteredDistances(n, 0.5, 1e-4);
  auto moved = [&](double last) {
    auto s = plain;
    moveLastSpacing(s, last);
    return s;
  };
  // A fine scan: between neighbouring values the nodes move by at most about 2 step
  // (the slope of the correction); a jump moves them by a sizeable part of a spacing.
  const double step = 1e-5;
  double largest = 0;
  auto previous = moved(0.002);
  for (double last = 0.002 + step; last < 0.2; last += step) {
    const auto next = moved(last);
    for (int j = 0; j < n; ++j) largest = std::max(largest, std::abs(next[j] - previous[j]));
    previous = next;
  }
  EXPECT_LT(largest, 10 * step);
}
