#include "passageMesh/blade/BladeSampler.hpp"

#include <gtest/gtest.h>

#include "passageMesh/blade/BladeShape.hpp"
#include "passageMesh/blade/BladeValidity.hpp"

using namespace passageMesh;

TEST(BladeSampler, DrawsValidBladesInsideTheBoxDeterministically) {
  const auto range = BladeParameterRange::readDefault();
  BladeSampler a(range, 42), b(range, 42), c(range, 43);
  for (int k = 0; k < 100; ++k) {
    const BladeParameters p = a.next();
    EXPECT_TRUE(range.contains(p));
    EXPECT_TRUE(checkBladeValidity(BladeShape(p)).valid);
    EXPECT_EQ(p.toArray(), b.next().toArray());
  }
  EXPECT_NE(a.next().toArray(), c.next().toArray());
  EXPECT_GT(a.accepted(), 0.5 * a.drawn());  // the box is mostly valid blades
}

TEST(BladeSampler, UniformVariatesAreInUnitInterval) {
  std::mt19937_64 rng(1);
  double lo = 1, hi = 0;
  for (int k = 0; k < 10000; ++k) {
    const double u = uniform01(rng);
    lo = std::min(lo, u);
    hi = std::max(hi, u);
  }
  EXPECT_GE(lo, 0.0);
  EXPECT_LT(hi, 1.0);
  EXPECT_LT(lo, 0.01);
  EXPECT_GT(hi, 0.99);
}
