#pragma once
// Every evaluation of a run, in the order the run defines (not the order threads happened
// to finish): what iterOptimize writes as its history and plots as its convergence.
#include <Eigen/Core>
#include <vector>

namespace passageMesh {

struct Evaluation {
  long index = 0;           // 0, 1, 2, ...
  Eigen::VectorXd point;    // as the objective saw it (BoxProblem::evaluatedPoint)
  double value = 0;
  double bestSoFar = 0;     // the largest value among evaluations 0..index
};

using OptimizationHistory = std::vector<Evaluation>;

}  // namespace passageMesh
