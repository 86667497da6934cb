#include "passageMesh/optimize/Objective.hpp"

#include "passageMesh/core/ParallelFor.hpp"

namespace passageMesh {

BatchObjective evaluateInParallel(PointObjective objective, int threads) {
  return [objective = std::move(objective), threads](const std::vector<Eigen::VectorXd>& points) {
    std::vector<double> values(points.size());
    parallelFor(static_cast<int>(points.size()), threads,
                [&](int i) { values[i] = objective(points[i]); });
    return values;
  };
}

}  // namespace passageMesh
