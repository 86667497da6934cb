#include "passageMesh/policy/ActionSearch.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace passageMesh;

namespace {

// A peak at (0.5, -0.5, 0.5): 1 minus the distance to it.
const BatchObjective peak = evaluateInParallel(
    [](const Eigen::VectorXd& x) {
      const Eigen::Vector3d optimum(0.5, -0.5, 0.5);
      return 1 - (x - optimum).norm();
    },
    1);

}  // namespace

TEST(ActionSearch, TheScaledBoxIsMinusOneToOneInEveryAction) {
  const BoxProblem box = scaledActionBox(4);
  ASSERT_EQ(box.dimension(), 4);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(box.lower[k], -1.0);
    EXPECT_EQ(box.upper[k], 1.0);
  }
}

TEST(ActionSearch, FindsThePeakInTheWholeBoxAndTheBestOnTheBoundOfAPartOfIt) {
  const OptimizationResult whole = searchActions({0, 0, 0}, peak, 400, 1, 0.15);
  EXPECT_NEAR(whole.bestValue, 1, 0.02);
  // The first action held at or below 0: the best there is on that bound, (0, -0.5, 0.5).
  BoxProblem part = scaledActionBox(3);
  part.upper[0] = 0;
  const OptimizationResult held = searchActions(part, {-0.5, 0, 0}, peak, 400, 1, 0.15);
  EXPECT_LE(held.best[0], 0.0);
  EXPECT_NEAR(held.bestValue, 0.5, 0.02);
  ASSERT_EQ(held.history.size(), 400u);
  for (const Evaluation& e : held.history) EXPECT_LE(e.point[0], 0.0);
}
