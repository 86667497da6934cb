#pragma once
// Maximising an objective over a box in as few evaluations as possible (issue 5,
// iterOptimize). Methods, by name (docs/optimization.md):
//   cmaes    CMA-ES with IPOP restarts (our own, on Eigen); evaluates a whole population
//            per batch, the natural parallel method: the default. The last 15 % of the
//            budget go to a pattern search from the best point (one mesh at a time)
//   bobyqa, sbplx, cobyla    NLopt's local methods, restarted from random points
//   crs2lm, isres            NLopt's global methods, restarted likewise
//   drl      the paper's single-step actor-critic with the condition fixed (registered by
//            the policy library, DrlOptimizer.hpp)
// A run is deterministic for a seed: the same options give the same history whatever the
// number of threads.
#include <Eigen/Core>
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "passageMesh/optimize/BoxProblem.hpp"
#include "passageMesh/optimize/Objective.hpp"
#include "passageMesh/optimize/OptimizationHistory.hpp"

namespace passageMesh {

struct OptimizationProgress {
  long evaluations = 0;  // done so far
  long budget = 0;
  double bestValue = 0;
};

struct OptimizerOptions {
  std::string method = "cmaes";
  long budget = 1000;         // evaluations; a run uses exactly this many unless stopped
  std::uint64_t seed = 1;
  // Threads for NLopt restarts run side by side (0 = all cores). CMA-ES hands its
  // population to the objective in one batch: evaluateInParallel decides its threads.
  int threads = 0;
  // Set (for example by a SIGINT handler) to end the run at the next evaluation or batch;
  // the result then holds the history so far.
  const std::atomic<bool>* stop = nullptr;
  // Called after every batch (CMA-ES) or evaluation (NLopt), from one thread at a time.
  std::function<void(const OptimizationProgress&)> progress;
  // Where the first start is (the case's meshDict); empty = the box centre. Later
  // restarts start from random points.
  std::optional<Eigen::VectorXd> start;
  // NLopt: restarts run side by side in rounds of this many, each with an equal share of
  // the budget left (local methods usually converge sooner and leave the rest to the next
  // round). The history depends on this number, not on `threads`; 1 = one restart at a
  // time, each with all the budget left.
  int restartsPerRound = 1;
  // cmaes: the share of the budget kept for a final pattern search (Hooke & Jeeves) from
  // the best point, which climbs to the edges where the mesh quality peaks; 0 = CMA-ES
  // to the end. CMA-ES always gets the start and its first population. Measured on the
  // tutorials in docs/optimization.md.
  double patternSearchShare = 0.15;
};

struct OptimizationResult {
  std::string method;
  Eigen::VectorXd best;      // as evaluated (integer dimensions rounded)
  double bestValue = 0;
  long evaluations = 0;
  int restarts = 0;          // starts of the method, the first included
  long patternSearchEvaluations = 0;  // of `evaluations`, those of the final pattern search
  bool stopped = false;      // ended by the stop flag before the budget was used
  OptimizationHistory history;
};

// A method defined in a library above this one (the policy library's "drl"). It searches
// the unit cube [0, 1]^dimension, handing batches of points to `evaluate`, which returns
// their values: all of them, the first ones only when the budget ends, none when the
// stop flag is set (the method must then return). Returns the number of starts it made.
using UnitCubeEvaluator = std::function<std::vector<double>(const std::vector<Eigen::VectorXd>&)>;
using ExternalOptimizerMethod = std::function<int(int dimension, const Eigen::VectorXd& unitStart,
                                                  const UnitCubeEvaluator& evaluate,
                                                  const OptimizerOptions& options)>;
// Makes `name` selectable (optimizerMethods lists it last); registering a name again
// replaces the method. Not thread-safe: register before optimising.
void registerOptimizerMethod(const std::string& name, ExternalOptimizerMethod method);

// The selectable method names, the default first.
const std::vector<std::string>& optimizerMethods();

// Throws std::invalid_argument for an unknown method, a bad box, budget < 1, a
// patternSearchShare outside [0, 1] or a start point outside the box; exceptions from
// the objective pass through.
OptimizationResult optimize(const BoxProblem& problem, const BatchObjective& objective,
                            const OptimizerOptions& options);

}  // namespace passageMesh
