#include "EvaluationLog.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace passageMesh::optimizeDetail {

EvaluationLog::EvaluationLog(const BoxProblem& problem, const BatchObjective& objective,
                             const OptimizerOptions& options)
    : problem_(problem), objective_(objective), options_(options),
      unitStart_(options.start ? problem.toUnit(*options.start) : Eigen::VectorXd()) {
  history_.reserve(static_cast<std::size_t>(options.budget));
}

bool EvaluationLog::stopRequested() const {
  return options_.stop != nullptr && options_.stop->load();
}

Eigen::VectorXd EvaluationLog::evaluatedPoint(const Eigen::VectorXd& unitPoint) const {
  // The start as the caller gave it: the round trip through the unit cube can move a value
  // by an ulp (yOut = -0.01 C of the defaults did), and the first evaluation must be the
  // start itself.
  if (options_.start && unitPoint == unitStart_)
    return problem_.evaluatedPoint(*options_.start);
  return problem_.evaluatedPoint(problem_.fromUnit(unitPoint));
}

std::vector<double> EvaluationLog::callObjective(const std::vector<Eigen::VectorXd>& points) const {
  std::vector<double> values = objective_(points);
  if (values.size() != points.size())
    throw std::runtime_error("optimize: the objective returned " + std::to_string(values.size()) +
                             " values for " + std::to_string(points.size()) + " points");
  for (double& v : values)
    if (std::isnan(v)) v = -std::numeric_limits<double>::infinity();
  return values;
}

std::vector<double> EvaluationLog::evaluate(const std::vector<Eigen::VectorXd>& unitPoints) {
  if (stopRequested()) {
    stopped_ = true;
    return {};
  }
  const std::size_t count = std::min<std::size_t>(unitPoints.size(), std::max(0L, remaining()));
  std::vector<Eigen::VectorXd> points;
  points.reserve(count);
  for (std::size_t i = 0; i < count; ++i) points.push_back(evaluatedPoint(unitPoints[i]));
  const std::vector<double> values = callObjective(points);
  for (std::size_t i = 0; i < count; ++i) record(points[i], values[i]);
  reportProgress();
  return values;
}

void EvaluationLog::record(const Eigen::VectorXd& point, double value) {
  Evaluation e;
  e.index = static_cast<long>(history_.size());
  e.point = point;
  e.value = value;
  if (bestIndex_ < 0 || value > history_[bestIndex_].value) bestIndex_ = e.index;
  e.bestSoFar = bestIndex_ == e.index ? value : history_[bestIndex_].value;
  history_.push_back(std::move(e));
}

void EvaluationLog::reportProgress() const {
  if (!options_.progress || history_.empty()) return;
  options_.progress({static_cast<long>(history_.size()), options_.budget, history_.back().bestSoFar});
}

double EvaluationLog::bestValue() const {
  return bestIndex_ < 0 ? -std::numeric_limits<double>::infinity() : history_[bestIndex_].value;
}

Eigen::VectorXd EvaluationLog::bestUnitPoint() const {
  return bestIndex_ < 0 ? Eigen::VectorXd() : problem_.toUnit(history_[bestIndex_].point);
}

OptimizationResult EvaluationLog::result(const std::string& method, int restarts) const {
  OptimizationResult r;
  r.method = method;
  r.evaluations = static_cast<long>(history_.size());
  r.restarts = restarts;
  r.patternSearchEvaluations = patternSearchEvaluations_;
  r.stopped = stopped_ && remaining() > 0;
  r.history = history_;
  r.bestValue = bestValue();
  if (bestIndex_ >= 0) r.best = history_[bestIndex_].point;
  return r;
}

std::uint64_t derivedSeed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + (stream + 1) * 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace passageMesh::optimizeDetail
