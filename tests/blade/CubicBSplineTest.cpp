#include "passageMesh/blade/CubicBSpline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

using namespace passageMesh;

TEST(CubicBSpline, KnotsAreClampedAndUniform) {
  const auto k = clampedUniformKnots(12);
  ASSERT_EQ(k.size(), 16u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(k[i], 0.0);
    EXPECT_EQ(k[12 + i], 1.0);
  }
  for (int i = 1; i <= 8; ++i) EXPECT_NEAR(k[3 + i], i / 9.0, 1e-15);
}

TEST(CubicBSpline, BasisIsPartitionOfUnityAndDerivativesMatchFiniteDifferences) {
  for (int n : {4, 8, 12}) {
    for (double u : {0.0, 0.03, 0.2, 0.5, 0.77, 0.999, 1.0}) {
      const CubicBasis b = cubicBasis(n, u);
      EXPECT_NEAR(std::accumulate(b.value.begin(), b.value.end(), 0.0), 1.0, 1e-14);
      EXPECT_NEAR(std::accumulate(b.d1.begin(), b.d1.end(), 0.0), 0.0, 1e-11);
      // Compare the spline of control values c_k = k^2 with finite differences.
      std::vector<double> c(n);
      for (int k = 0; k < n; ++k) c[k] = k * k + 0.3 * k;
      auto f = [&](double x) {
        const CubicBasis bx = cubicBasis(n, x);
        return combine(bx, bx.value, c.data());
      };
      const double h = 1e-5;
      const double uc = std::clamp(u, 2 * h, 1 - 2 * h);  // stay inside one side
      const CubicBasis bc = cubicBasis(n, uc);
      EXPECT_NEAR(combine(bc, bc.d1, c.data()), (f(uc + h) - f(uc - h)) / (2 * h), 1e-5);
      EXPECT_NEAR(combine(bc, bc.d2, c.data()), (f(uc + h) - 2 * f(uc) + f(uc - h)) / (h * h),
                  2e-2 * std::max(1.0, std::abs(combine(bc, bc.d2, c.data()))));
    }
  }
}

TEST(CubicBSpline, ClampedEndsInterpolateEndValues) {
  std::vector<double> c{3, 1, 4, 1, 5, 9, 2, 6};
  const CubicBasis b0 = cubicBasis(8, 0.0), b1 = cubicBasis(8, 1.0);
  EXPECT_DOUBLE_EQ(combine(b0, b0.value, c.data()), 3.0);
  EXPECT_DOUBLE_EQ(combine(b1, b1.value, c.data()), 6.0);
}

TEST(PiecewiseCubicCurve, AgreesWithTheBasisAndItsDerivativesEverywhere) {
  // The per-span polynomials must give the spline of the basis recursion: point, first
  // and second derivative, in every span, at the knots and at the clamped ends.
  for (int n : {4, 5, 9, 16}) {
    std::vector<Eigen::Vector2d> control;
    for (int k = 0; k < n; ++k) control.emplace_back(std::cos(0.7 * k) + 0.1 * k * k, std::sin(1.3 * k) - 0.2 * k);
    const PiecewiseCubicCurve curve(control.data(), n);
    for (int m = 0; m <= 200; ++m) {
      const double u = m / 200.0;
      const CubicBasis b = cubicBasis(n, u);
      const Eigen::Vector2d p = combine(b, b.value, control.data()), d1 = combine(b, b.d1, control.data()),
                            d2 = combine(b, b.d2, control.data());
      Eigen::Vector2d cp, cd1, cd2;
      curve.evaluate(u, cp, cd1, cd2);
      const double scale = 1 + d2.norm();
      EXPECT_LT((cp - p).norm(), 1e-12) << "n " << n << " u " << u;
      EXPECT_LT((cd1 - d1).norm(), 1e-10 * scale) << "n " << n << " u " << u;
      EXPECT_LT((cd2 - d2).norm(), 1e-9 * scale) << "n " << n << " u " << u;
      EXPECT_EQ(curve.point(u), cp);
    }
  }
}
