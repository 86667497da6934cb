#include "passageMesh/policy/ActionSearch.hpp"

namespace passageMesh {

OptimizationResult searchActions(const std::vector<double>& start, const BatchObjective& objective, long budget,
                                 std::uint64_t seed, double patternSearchShare) {
  const auto size = static_cast<Eigen::Index>(start.size());
  BoxProblem box;
  box.lower = Eigen::VectorXd::Constant(size, -1.0);
  box.upper = Eigen::VectorXd::Constant(size, 1.0);
  OptimizerOptions options;
  options.budget = budget;
  options.seed = seed;
  options.start = Eigen::Map<const Eigen::VectorXd>(start.data(), size);
  options.patternSearchShare = patternSearchShare;
  return optimize(box, objective, options);
}

}  // namespace passageMesh
