// Thompson's equations with P = Q = 0 on the annulus between two concentric circles with
// uniform boundary nodes: the exact grid has radii in geometric progression (eta is
// harmonic, so linear in log r). The discrete solution must approach it at second order,
// and the multigrid solver must reach the same discrete solution as line relaxation.
#include "passageMesh/mesh/ThompsonSolver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "AnnulusTestData.hpp"
#include "passageMesh/mesh/ThompsonMultigrid.hpp"

using namespace passageMesh;
using testData::annulus;
using testData::innerRadius;
using testData::outerRadius;

namespace {

// Largest radial error against the harmonic grid, relative to the outer radius.
double radialError(const StructuredBlock& o) {
  double error = 0;
  for (int j = 0; j < o.nj; ++j) {
    const double exact = innerRadius * std::pow(outerRadius / innerRadius, j / (o.nj - 1.0));
    for (int i = 0; i + 1 < o.ni; ++i)
      error = std::max(error, std::abs(std::hypot(o.xAt(i, j), o.yAt(i, j)) - exact) / outerRadius);
  }
  return error;
}

double annulusError(int n, int nj, ThompsonReport* report = nullptr) {
  StructuredBlock o = annulus(n, nj);
  ThompsonOptions options;
  options.tolerance = 1e-12;
  options.maxSweeps = 200000;
  GridControl none;
  const ThompsonReport r = solveThompson(o, none, options);
  if (report) *report = r;
  return radialError(o);
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

// The convergence measure of a grid with one node not a number is not a number, wherever
// the node lies (it ends iterateUntilConverged's loop as failed): the residual's running
// maximum must not let a later finite node replace it.
TEST(ThompsonSolver, ResidualOfAGridWithANaNNodeIsNotANumber) {
  const StructuredBlock clean = annulus(32, 9);
  const GridControl none;
  const MovingRows rows;
  const double r = thompsonResidual(clean, none, rows);
  EXPECT_TRUE(std::isfinite(r)) << r;
  for (const auto& [i, j] : {std::pair{16, 1}, std::pair{0, 4}, std::pair{30, 7}}) {
    StructuredBlock o = clean;
    o.xAt(i, j) = std::nan("");
    EXPECT_TRUE(std::isnan(thompsonResidual(o, none, rows))) << "NaN at node (" << i << ", " << j << ")";
  }
}

// The loop every solve runs: converged at the tolerance, failed at a residual not a number,
// stopped where the residual has not halved over the stall window.
TEST(ThompsonSolver, IterateUntilConvergedStopsAtTheToleranceANaNOrAStall) {
  const auto run = [](std::vector<double> residuals, int stallWindow) {
    std::size_t k = 0;
    return iterateUntilConverged(
        100, 1e-9, [&] { ++k; }, [&] { return residuals[std::min(k, residuals.size()) - 1]; }, stallWindow);
  };
  ThompsonReport r = run({1, 1e-3, 1e-10, 5}, 0);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.sweeps, 3);
  EXPECT_EQ(r.residual, 1e-10);
  r = run({1, std::nan(""), 1e-10}, 0);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.sweeps, 2);
  r = run({1, 0.9, 0.8, 0.7, 0.6, 0.5}, 3);  // 0.7 is not half of 1: stalled at sweep 4
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.sweeps, 4);
  r = run({1, 0.4, 0.1, 0.04, 0.01, 1e-10}, 3);  // halves within every window
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.sweeps, 6);
  r = run({1}, 0);  // never below the tolerance: all 100 sweeps
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.sweeps, 100);
}

// Even and odd loops, rows with and without a one-row last interval, one or two fixed rows
// at the wall and at the outer loop: multigrid reaches line relaxation's solution, in
// few cycles.
TEST(ThompsonMultigrid, ReachesTheLineRelaxationSolutionInFewCycles) {
  struct Case {
    int n, nj, below, above;
  };
  for (const Case& c : {Case{128, 34, 2, 1}, Case{127, 33, 2, 1}, Case{90, 40, 1, 1},
                        Case{101, 30, 2, 2}}) {
    MovingRows rows;
    rows.below = c.below;
    rows.above = c.above;
    StructuredBlock byLines = annulus(c.n, c.nj, 0.05), byMultigrid = byLines;
    GridControl none;
    ThompsonOptions single;
    single.tolerance = 1e-12;
    single.maxSweeps = 200000;
    single.rows = rows;
    ASSERT_TRUE(solveThompson(byLines, none, single).converged);
    MultigridOptions mg;
    mg.tolerance = 1e-12;
    mg.maxCycles = 40;
    mg.rows = rows;
    const MultigridReport r = solveThompsonMultigrid(byMultigrid, none, mg);
    EXPECT_TRUE(r.converged) << c.n << " x " << c.nj << ": residual " << r.residual;
    EXPECT_GT(r.levels, 2);
    double largest = 0;
    for (std::size_t k = 0; k < byLines.x.size(); ++k)
      largest = std::max(largest, std::hypot(byLines.x[k] - byMultigrid.x[k], byLines.y[k] - byMultigrid.y[k]));
    EXPECT_LT(largest, 1e-9) << c.n << " x " << c.nj;
    std::printf("%d x %d, rows %d/%d: %d cycles, %d levels\n", c.n, c.nj, c.below, c.above,
                r.cycles, r.levels);
  }
}
