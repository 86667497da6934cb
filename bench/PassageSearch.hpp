#pragma once
// The per-passage best a policy is compared with: CMA-ES (iterOptimize's default method)
// over one sampler passage's meshing parameters in scaled units ([-1, 1] per parameter),
// from `start` (the defaults' action), seed 1, with `budget` meshes built on all cores.
#include <vector>

#include "passageMesh/policy/ActionSearch.hpp"
#include "passageMesh/policy/PolicyEnvironment.hpp"

namespace passageMesh::bench {

inline OptimizationResult searchPassage(const EpisodeTask& task, const std::vector<double>& start, long budget) {
  const PointObjective q = [&task](const Eigen::VectorXd& x) {
    return task.reward(std::vector<double>(x.data(), x.data() + x.size()));
  };
  return searchActions(start, evaluateInParallel(q, 0), budget, 1, OptimizerOptions{}.patternSearchShare);
}

}  // namespace passageMesh::bench
