#pragma once
// What the optimiser maximises. The methods hand the objective batches of points (CMA-ES a
// whole population at once) so that it can evaluate them in parallel; it returns the
// values by index, which keeps a run independent of the thread count. Points come as
// BoxProblem::evaluatedPoint gives them (inside the box, integer dimensions rounded).
#include <Eigen/Core>
#include <functional>
#include <vector>

namespace passageMesh {

// values[i] belongs to points[i]; values must have points.size() entries. NLopt methods
// that run restarts side by side call it from several threads at once (one point per
// call), so it must be safe to call concurrently.
using BatchObjective = std::function<std::vector<double>(const std::vector<Eigen::VectorXd>& points)>;
using PointObjective = std::function<double(const Eigen::VectorXd& point)>;

// A batch objective that evaluates a point function on up to `threads` threads
// (parallelFor; 0 = all cores). The point function must be safe to call concurrently.
BatchObjective evaluateInParallel(PointObjective objective, int threads);

}  // namespace passageMesh
