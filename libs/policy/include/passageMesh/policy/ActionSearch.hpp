#pragma once
// A search over one passage's actions: CMA-ES (iterOptimize's default method) in the scaled
// meshing parameters, [-1, 1] per action entry, from `start`. policyTrain's searches
// (PolicyTrainer) and the benches' per-passage bests (bench/PassageSearch.hpp) both run it.
#include <cstdint>
#include <vector>

#include "passageMesh/optimize/Optimizer.hpp"

namespace passageMesh {

// The whole scaled box: [-1, 1] in each of `size` actions.
BoxProblem scaledActionBox(int size);

// `patternSearchShare`: OptimizerOptions's (0: CMA-ES to the end, every batch a whole
// population). The history holds every evaluation in order, the start's first.
OptimizationResult searchActions(const std::vector<double>& start, const BatchObjective& objective, long budget,
                                 std::uint64_t seed, double patternSearchShare);
// The same within `box`, a part of the scaled box (e.g. one action held to one side of a
// value: bench/policyLocalSearch); `start` must lie in it.
OptimizationResult searchActions(const BoxProblem& box, const std::vector<double>& start,
                                 const BatchObjective& objective, long budget, std::uint64_t seed,
                                 double patternSearchShare);

}  // namespace passageMesh
