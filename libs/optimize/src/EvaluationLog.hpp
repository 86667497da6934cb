#pragma once
// The bookkeeping every method shares (private to the library): the budget, the stop
// flag, the history with its running best, progress reports, and the way from the unit
// cube the methods search to the points the objective sees.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "passageMesh/optimize/Optimizer.hpp"

namespace passageMesh::optimizeDetail {

class EvaluationLog {
 public:
  EvaluationLog(const BoxProblem& problem, const BatchObjective& objective,
                const OptimizerOptions& options);

  const BoxProblem& problem() const { return problem_; }
  const OptimizerOptions& options() const { return options_; }
  long remaining() const { return options_.budget - static_cast<long>(history_.size()); }
  bool stopRequested() const;
  bool finished() const { return stopped_ || remaining() <= 0; }
  void markStopped() { stopped_ = true; }

  // The point the objective sees for a point of the unit cube.
  Eigen::VectorXd evaluatedPoint(const Eigen::VectorXd& unitPoint) const;
  // Calls the objective (it may run concurrently with other calls) and checks its answer;
  // a NaN value counts as -infinity, the worst.
  std::vector<double> callObjective(const std::vector<Eigen::VectorXd>& points) const;

  // Evaluates the first remaining() of the unit-cube points as one batch, records them
  // and reports progress. When the stop flag is set nothing is evaluated, the run is
  // marked stopped and the result is empty.
  std::vector<double> evaluate(const std::vector<Eigen::VectorXd>& unitPoints);

  // Records an evaluation made elsewhere (NLopt restarts merge theirs in restart order).
  void record(const Eigen::VectorXd& point, double value);
  void reportProgress() const;
  // The largest value so far; -infinity before the first evaluation.
  double bestValue() const;
  // The best point so far in the unit cube (as evaluated: integer dimensions rounded);
  // empty before the first evaluation.
  Eigen::VectorXd bestUnitPoint() const;

  // Evaluations made by a final pattern search (CMA-ES), reported in the result.
  void countPatternSearch(long evaluations) { patternSearchEvaluations_ += evaluations; }

  OptimizationResult result(const std::string& method, int restarts) const;

 private:
  const BoxProblem& problem_;
  const BatchObjective& objective_;
  const OptimizerOptions& options_;
  Eigen::VectorXd unitStart_;  // options_.start in the unit cube (empty without a start)
  OptimizationHistory history_;
  long bestIndex_ = -1;
  bool stopped_ = false;
  long patternSearchEvaluations_ = 0;
};

// Splits a seed into independent seeds for restarts or streams (splitmix64).
std::uint64_t derivedSeed(std::uint64_t seed, std::uint64_t stream);

}  // namespace passageMesh::optimizeDetail
