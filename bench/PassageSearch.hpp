#pragma once
// The per-passage best a policy is compared with: CMA-ES (iterOptimize's default method)
// over one sampler passage's meshing parameters in scaled units ([-1, 1] per parameter),
// from `start` (the defaults' action), seed 1, with `budget` meshes built on all cores.
#include <vector>

#include "passageMesh/optimize/Optimizer.hpp"
#include "passageMesh/policy/PolicyEnvironment.hpp"

namespace passageMesh::bench {

inline OptimizationResult searchPassage(const EpisodeTask& task, const std::vector<double>& start, long budget) {
  const auto size = static_cast<Eigen::Index>(start.size());
  BoxProblem box;
  box.lower = Eigen::VectorXd::Constant(size, -1.0);
  box.upper = Eigen::VectorXd::Constant(size, 1.0);
  OptimizerOptions options;
  options.budget = budget;
  options.seed = 1;
  options.start = Eigen::Map<const Eigen::VectorXd>(start.data(), size);
  const PointObjective q = [&task](const Eigen::VectorXd& x) {
    return task.reward(std::vector<double>(x.data(), x.data() + x.size()));
  };
  return optimize(box, evaluateInParallel(q, 0), options);
}

}  // namespace passageMesh::bench
