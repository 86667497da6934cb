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

TEST(BladeSampler, HalfLogUniformEdgeRadiiMakeSharpEdgesCommonAndStayInTheBox) {
  const auto range = BladeParameterRange::readDefault();
  EXPECT_EQ(BladeParameters::names()[BladeParameters::radiusLeIndex], "radiusLe");
  EXPECT_EQ(BladeParameters::names()[BladeParameters::radiusTeIndex], "radiusTe");
  BladeSampler uniform(range, 7), mixed(range, 7, EdgeRadiusDraw::halfLogUniform),
      again(range, 7, EdgeRadiusDraw::halfLogUniform);
  // A trailing edge as sharp as STD10's or SIRT's (1e-4 chord) or sharper.
  const double sharp = 3e-4;
  int sharpUniform = 0, sharpMixed = 0, roundMixed = 0;
  const int n = 400;
  for (int k = 0; k < n; ++k) {
    sharpUniform += uniform.next().radiusTe < sharp;
    const BladeParameters p = mixed.next();
    EXPECT_TRUE(range.contains(p));
    EXPECT_EQ(p.toArray(), again.next().toArray());
    sharpMixed += p.radiusTe < sharp;
    roundMixed += p.radiusTe > 0.006;  // the upper half of the range
  }
  // Uniform: P(radiusTe < 3e-4) = 0.023; half log-uniform: 0.5 ln(10) / ln(400) + 0.011 = 0.20.
  EXPECT_LT(sharpUniform, 0.06 * n);
  EXPECT_GT(sharpMixed, 0.12 * n);
  EXPECT_GT(roundMixed, 0.15 * n);  // round edges stay common (expected 0.5 * 0.5 + 0.5 * 0.12 = 0.31)
}

// The range box holds the edge angles relative to the stagger (so that one box fits blades
// of every stagger); the two coordinate maps are each other's inverse.
TEST(BladeParameterRange, RangeCoordinatesHoldTheEdgeAnglesRelativeToTheStagger) {
  BladeSampler sampler(BladeParameterRange::readDefault(), 5);
  for (int k = 0; k < 20; ++k) {
    const BladeParameters p = sampler.next();
    const auto v = BladeParameterRange::toRangeCoordinates(p);
    EXPECT_EQ(v[3], p.stagger);
    EXPECT_DOUBLE_EQ(v[4], p.thetaLe - p.stagger);
    EXPECT_DOUBLE_EQ(v[5], p.thetaTe - p.stagger);
    EXPECT_EQ(v[2], p.chord);
    const auto back = BladeParameterRange::fromRangeCoordinates(v).toArray();
    const auto original = p.toArray();
    for (int i = 0; i < BladeParameters::size; ++i) EXPECT_NEAR(back[i], original[i], 1e-12) << i;
  }
}
