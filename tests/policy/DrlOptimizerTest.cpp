// iterOptimize's "drl" method on the optimiser's synthetic objectives.
#include "passageMesh/policy/DrlOptimizer.hpp"

#include <gtest/gtest.h>

#include "passageMesh/optimize/Optimizer.hpp"
#include "passageMesh/optimize/SyntheticObjectives.hpp"

using namespace passageMesh;

TEST(DrlOptimizer, UsesTheWholeBudgetStartsAtTheStartAndClimbsTheBowl) {
  registerDrlOptimizer();
  const auto& methods = optimizerMethods();
  ASSERT_NE(std::find(methods.begin(), methods.end(), "drl"), methods.end());
  const SyntheticProblem bowl = shiftedBowl();
  OptimizerOptions options;
  options.method = "drl";
  options.budget = 200;
  options.seed = 3;
  options.start = bowl.box.evaluatedPoint(0.5 * (bowl.box.lower + bowl.box.upper));
  const BatchObjective objective = evaluateInParallel(bowl.objective, 2);
  const OptimizationResult r = optimize(bowl.box, objective, options);
  ASSERT_EQ(r.evaluations, 200);
  ASSERT_EQ(r.history.size(), 200u);
  EXPECT_EQ(r.history.front().point, *options.start);
  const double start = r.history.front().value;
  EXPECT_GT(r.bestValue, start + 0.05) << "start " << start;
  // Deterministic for a seed, whatever the threads.
  const OptimizationResult again = optimize(bowl.box, evaluateInParallel(bowl.objective, 1), options);
  EXPECT_EQ(again.bestValue, r.bestValue);
  EXPECT_EQ(again.best, r.best);
}
