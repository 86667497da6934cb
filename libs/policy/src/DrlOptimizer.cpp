#include "passageMesh/policy/DrlOptimizer.hpp"

#include <algorithm>

#include "passageMesh/optimize/Optimizer.hpp"
#include "passageMesh/policy/PolicyTrainer.hpp"

namespace passageMesh {

namespace {

// One constant state; the reward comes from the optimiser's evaluator (FixedStateRollouts).
class FixedStateEnvironment final : public PolicyEnvironment {
 public:
  FixedStateEnvironment(int stateSize, std::vector<double> start)
      : stateSize_(stateSize), start_(std::move(start)) {}
  int stateSize() const override { return stateSize_; }
  int actionSize() const override { return static_cast<int>(start_.size()); }
  EpisodeTask draw(std::uint64_t, std::uint64_t, EpisodePurpose) const override {
    return EpisodeTask{std::vector<double>(static_cast<std::size_t>(stateSize_), 0.0), nullptr};
  }
  std::vector<double> defaultAction() const override { return start_; }

 private:
  int stateSize_;
  std::vector<double> start_;
};

struct BudgetEnded {};

// Actions in [-1, 1] -> unit-cube points -> the optimiser's evaluations.
class FixedStateRollouts final : public RolloutEvaluator {
 public:
  explicit FixedStateRollouts(const UnitCubeEvaluator& evaluate) : evaluate_(evaluate) {}
  std::vector<double> rewards(const std::vector<EpisodeTask>&, const PolicyBatch& actions,
                              const EpisodeRange&) override {
    std::vector<Eigen::VectorXd> points;
    for (long i = 0; i < actions.rows(); ++i)
      points.push_back(((actions.row(i).transpose().array() + 1.0) * 0.5).matrix());
    std::vector<double> values = evaluate_(points);
    if (values.size() < points.size()) throw BudgetEnded{};
    // An invalid mesh is -1 already; -infinity (a NaN objective) would wreck the critic.
    for (double& v : values) v = std::max(v, -1.0);
    return values;
  }
  std::string description() const override { return "the optimiser's objective"; }

 private:
  const UnitCubeEvaluator& evaluate_;
};

int runDrl(int dimension, const Eigen::VectorXd& unitStart, const UnitCubeEvaluator& evaluate,
           const OptimizerOptions& optimizer) {
  // The start first, as every method does: the best is never worse than the start.
  if (evaluate({unitStart}).empty() || optimizer.budget == 1) return 1;
  PolicyTrainOptions o;
  o.episodes = optimizer.budget - 1;
  o.batchEpisodes = 16;
  o.noiseStartEpisodes = std::min<long>(o.noiseStartEpisodes, optimizer.budget / 10);
  o.validationPassages = 0;
  o.seed = optimizer.seed;
  o.actorStart = ActorStart::defaults;
  std::vector<double> start(static_cast<std::size_t>(dimension));
  for (int k = 0; k < dimension; ++k) start[static_cast<std::size_t>(k)] = 2.0 * unitStart[k] - 1.0;
  const FixedStateEnvironment environment(1, start);
  FixedStateRollouts rollouts(evaluate);
  PolicyTrainer trainer(o, environment, rollouts);
  try {
    trainer.run(optimizer.stop, {});
  } catch (const BudgetEnded&) {
    // the optimiser's budget or stop flag ended the run; its log holds every evaluation
  }
  return 1;
}

}  // namespace

void registerDrlOptimizer() { registerOptimizerMethod("drl", runDrl); }

}  // namespace passageMesh
