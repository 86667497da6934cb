// Thompson's equations with P = Q = 0 on the annulus between two concentric circles with
// uniform boundary nodes: the exact grid has radii in geometric progression (eta is
// harmonic, so linear in log r). The discrete solution must approach it at second order.
#include "passageMesh/mesh/ThompsonSolver.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace passageMesh;

namespace {

// Largest radial error of the converged grid, relative to the outer radius.
double annulusError(int n, int nj, ThompsonReport* report = nullptr) {
  const double r0 = 1.0, r1 = 4.0;
  StructuredBlock o;
  o.name = "OBlock";
  o.ni = n + 1;
  o.nj = nj;
  o.x.resize(static_cast<std::size_t>(o.ni) * nj);
  o.y.resize(o.x.size());
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i <= n; ++i) {
      const double theta = -2 * M_PI * (i % n) / n;            // clockwise, j outwards
      const double r = r0 + (r1 - r0) * j / (nj - 1.0);        // start: uniform radii
      o.xAt(i, j) = r * std::cos(theta);
      o.yAt(i, j) = r * std::sin(theta);
    }
  ThompsonOptions options;
  options.tolerance = 1e-12;
  options.maxSweeps = 200000;
  GridControl none;
  const ThompsonReport r = solveThompson(o, none, options);
  if (report) *report = r;
  double error = 0;
  for (int j = 0; j < nj; ++j) {
    const double exact = r0 * std::pow(r1 / r0, static_cast<double>(j) / (nj - 1));
    for (int i = 0; i < n; ++i)
      error = std::max(error, std::abs(std::hypot(o.xAt(i, j), o.yAt(i, j)) - exact) / r1);
  }
  return error;
}

}  // namespace

TEST(ThompsonSolver, ConcentricCirclesConvergeToTheHarmonicGridAtSecondOrder) {
  ThompsonReport report;
  const double coarse = annulusError(32, 9, &report);
  EXPECT_TRUE(report.converged) << report.sweeps << " sweeps, residual " << report.residual;
  const double medium = annulusError(64, 17);
  const double fine = annulusError(128, 33);
  std::printf("radial error: %.3e %.3e %.3e (ratios %.2f %.2f)\n", coarse, medium, fine,
              coarse / medium, medium / fine);
  EXPECT_LT(fine, 1e-3);
  EXPECT_GT(coarse / medium, 3.5);  // second order: each halving of h divides it by 4
  EXPECT_LT(coarse / medium, 4.5);
  EXPECT_GT(medium / fine, 3.5);
  EXPECT_LT(medium / fine, 4.5);
}

TEST(ThompsonSolver, RefusesBadSizes) {
  StructuredBlock o;
  o.ni = 3;
  o.nj = 3;
  o.x.assign(9, 0.0);
  o.y.assign(9, 0.0);
  GridControl none;
  EXPECT_THROW(solveThompson(o, none), std::invalid_argument);
}
