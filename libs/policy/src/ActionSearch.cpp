#include "passageMesh/policy/ActionSearch.hpp"

namespace passageMesh {

BoxProblem scaledActionBox(int size) {
  BoxProblem box;
  box.lower = Eigen::VectorXd::Constant(size, -1.0);
  box.upper = Eigen::VectorXd::Constant(size, 1.0);
  return box;
}

OptimizationResult searchActions(const std::vector<double>& start, const BatchObjective& objective, long budget,
                                 std::uint64_t seed, double patternSearchShare) {
  return searchActions(scaledActionBox(static_cast<int>(start.size())), start, objective, budget, seed,
                       patternSearchShare);
}

OptimizationResult searchActions(const BoxProblem& box, const std::vector<double>& start,
                                 const BatchObjective& objective, long budget, std::uint64_t seed,
                                 double patternSearchShare) {
  const auto size = static_cast<Eigen::Index>(start.size());
  OptimizerOptions options;
  options.budget = budget;
  options.seed = seed;
  options.start = Eigen::Map<const Eigen::VectorXd>(start.data(), size);
  options.patternSearchShare = patternSearchShare;
  return optimize(box, objective, options);
}

}  // namespace passageMesh
