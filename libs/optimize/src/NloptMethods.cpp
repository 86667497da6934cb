// NLopt's methods with restarts from random points until the budget is used. NLopt runs
// one method sequentially and asks for one point at a time, so the parallelism is in the
// restarts: a round runs restartsPerRound of them side by side, each with its own share
// of the budget, its own start and its own seed for NLopt's random numbers (thread-local
// in NLopt, seeded in the thread that runs the restart). A restart keeps its evaluations
// to itself; the round merges them into the history in restart order, so the history does
// not depend on how the restarts were spread over threads.
#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <stdexcept>
#include <utility>

#include "Methods.hpp"
#include "passageMesh/core/ParallelFor.hpp"

namespace passageMesh::optimizeDetail {

namespace {

const std::map<std::string, nlopt_algorithm>& algorithms() {
  static const std::map<std::string, nlopt_algorithm> table{
      {"bobyqa", NLOPT_LN_BOBYQA}, {"sbplx", NLOPT_LN_SBPLX},   {"cobyla", NLOPT_LN_COBYLA},
      {"crs2lm", NLOPT_GN_CRS2_LM}, {"isres", NLOPT_GN_ISRES}};
  return table;
}

// Where a restart ends by itself (unit-cube lengths): local methods converge; the global
// ones mostly run out of their share of the budget first.
constexpr double xTolerance = 1e-7;
constexpr double fTolerance = 1e-9;  // Q differences this small are meaningless
constexpr double initialStep = 0.1;

// The live count and best value for progress reports while restarts run side by side.
class SharedProgress {
 public:
  explicit SharedProgress(const EvaluationLog& log) : options_(log.options()), done_(log.options().budget - log.remaining()) {}
  void add(double value, double bestBefore) {
    if (!options_.progress) return;
    std::lock_guard<std::mutex> lock(mutex_);
    ++done_;
    best_ = std::max({best_, value, bestBefore});
    options_.progress({done_, options_.budget, best_});
  }

 private:
  const OptimizerOptions& options_;
  std::mutex mutex_;
  long done_;
  double best_ = -std::numeric_limits<double>::infinity();
};

struct Restart {
  long budget = 0;
  std::uint64_t seed = 0;
  Eigen::VectorXd start;  // unit cube
  std::vector<std::pair<Eigen::VectorXd, double>> evaluations;
  bool stopped = false;
  nlopt_result outcome = NLOPT_SUCCESS;
};

struct CallbackData {
  const EvaluationLog* log;
  SharedProgress* progress;
  double bestBefore;
  Restart* restart;
  nlopt_opt opt;
};

double minusObjective(unsigned n, const double* x, double* /*gradient: derivative-free*/, void* data) {
  auto& d = *static_cast<CallbackData*>(data);
  Restart& r = *d.restart;
  if (static_cast<long>(r.evaluations.size()) >= r.budget || d.log->stopRequested()) {
    r.stopped = static_cast<long>(r.evaluations.size()) < r.budget;
    nlopt_force_stop(d.opt);
    return std::numeric_limits<double>::max();
  }
  const Eigen::VectorXd point = d.log->evaluatedPoint(Eigen::Map<const Eigen::VectorXd>(x, n));
  const double value = d.log->callObjective({point})[0];
  r.evaluations.emplace_back(point, value);
  d.progress->add(value, d.bestBefore);
  // NLopt's methods cannot take infinities; the lowest finite value ranks the same.
  return std::isfinite(value) ? -value : std::numeric_limits<double>::max();
}

void runRestart(const EvaluationLog& log, nlopt_algorithm algorithm, SharedProgress& progress,
                double bestBefore, Restart& r) {
  const auto n = static_cast<unsigned>(log.problem().dimension());
  std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)> opt(nlopt_create(algorithm, n), &nlopt_destroy);
  if (!opt) throw std::runtime_error("optimize: NLopt could not create its method");
  CallbackData data{&log, &progress, bestBefore, &r, opt.get()};
  nlopt_set_lower_bounds1(opt.get(), 0.0);
  nlopt_set_upper_bounds1(opt.get(), 1.0);
  nlopt_set_min_objective(opt.get(), &minusObjective, &data);
  nlopt_set_xtol_abs1(opt.get(), xTolerance);
  nlopt_set_ftol_abs(opt.get(), fTolerance);
  nlopt_set_initial_step1(opt.get(), initialStep);
  // One more than the share: the last call is refused by minusObjective, so a method that
  // would overrun its share cannot evaluate past it.
  nlopt_set_maxeval(opt.get(), static_cast<int>(std::min<long>(r.budget + 1, std::numeric_limits<int>::max())));
  nlopt_srand(static_cast<unsigned long>(r.seed));
  std::vector<double> x(r.start.data(), r.start.data() + r.start.size());
  double minimum = 0;
  r.outcome = nlopt_optimize(opt.get(), x.data(), &minimum);
}

}  // namespace

const std::vector<std::string>& nloptMethodNames() {
  // Tried and left out: Nelder-Mead and ESCH, which missed the two-peak test objective's
  // maximum in most runs of 3000 and 30000 evaluations (docs/optimization.md).
  static const std::vector<std::string> names{"bobyqa", "sbplx", "cobyla", "crs2lm", "isres"};
  return names;
}

int runNlopt(EvaluationLog& log, const std::string& method) {
  const nlopt_algorithm algorithm = algorithms().at(method);
  const BoxProblem& problem = log.problem();
  const OptimizerOptions& options = log.options();
  const int perRound = std::max(1, options.restartsPerRound);
  int starts = 0;
  while (!log.finished()) {
    if (log.stopRequested()) {
      log.markStopped();
      break;
    }
    const long left = log.remaining();
    const int count = static_cast<int>(std::min<long>(perRound, left));
    std::vector<Restart> round(count);
    for (int i = 0; i < count; ++i) {
      Restart& r = round[i];
      r.budget = left / count + (i < left % count ? 1 : 0);
      r.seed = derivedSeed(options.seed, static_cast<std::uint64_t>(starts + i));
      std::mt19937_64 rng(r.seed);
      r.start = starts + i == 0 ? problem.toUnit(options.start.value_or(problem.centre()))
                                : problem.toUnit(problem.randomPoint(rng));
    }
    const double bestBefore = log.bestValue();
    SharedProgress progress(log);
    parallelFor(count, options.threads,
                [&](int i) { runRestart(log, algorithm, progress, bestBefore, round[i]); });
    long used = 0;
    for (const Restart& r : round) {
      for (const auto& [point, value] : r.evaluations) log.record(point, value);
      used += static_cast<long>(r.evaluations.size());
      if (r.stopped) log.markStopped();
    }
    starts += count;
    if (used == 0 && !log.finished())
      throw std::runtime_error("optimize: NLopt's " + method + " evaluated nothing (NLopt result " +
                               std::to_string(static_cast<int>(round[0].outcome)) + ")");
  }
  log.reportProgress();
  return starts;
}

}  // namespace passageMesh::optimizeDetail
