// CMA-ES with IPOP restarts, after N. Hansen, "The CMA Evolution Strategy: A Tutorial"
// (arXiv:1604.00772), and Auger & Hansen 2005 for the restarts with doubling population.
// It minimises -f in the unit cube. Unlike textbook IPOP, the starts alternate between a
// local one, centred on the best point so far (the case's own parameters first) with a
// small step, and a global one from a random point with a large step: for the mesh
// quality most of the box is invalid (about 99 % of uniform random points for the
// tutorials) and the valid region around a working mesh is narrow, so random starts
// alone spend the budget on invalid meshes, while local starts alone never leave the
// first peak (docs/optimization.md). Bounds by a transformation: a sampled point is
// mirrored back into [0, 1] in every coordinate (periodic reflection), so every sample is
// feasible and the distribution near a bound stays close to the sampled Gaussian, where a
// clip would pile samples on the bound. Integer dimensions are rounded by the log, at
// evaluation only: the strategy itself stays continuous. The covariance update is the
// tutorial's 2016 default with negative weights for the worse half ("active" CMA-ES):
// measured on the tutorials (10 seeds, budget 1000) it lifted every median final Q, LS89's
// from 0.5363 to 0.5380 (docs/optimization.md). The last share of the budget
// (OptimizerOptions::patternSearchShare) goes to a pattern search from the best point
// (PatternSearch.cpp), which climbs the last bit that sampling reaches only by chance.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "Methods.hpp"
#include "passageMesh/blade/BladeSampler.hpp"  // uniform01

namespace passageMesh::optimizeDetail {

namespace {

// Standard normal variates by the Box-Muller transform of uniform01: the same numbers on
// every platform (std::normal_distribution's algorithm is left to the implementation).
class StandardNormal {
 public:
  explicit StandardNormal(std::uint64_t seed) : rng_(seed) {}
  double operator()() {
    if (hasSpare_) {
      hasSpare_ = false;
      return spare_;
    }
    const double radius = std::sqrt(-2 * std::log(1 - uniform01(rng_)));  // 1 - u > 0
    const double angle = 2 * M_PI * uniform01(rng_);
    spare_ = radius * std::sin(angle);
    hasSpare_ = true;
    return radius * std::cos(angle);
  }
  std::mt19937_64& engine() { return rng_; }

 private:
  std::mt19937_64 rng_;
  double spare_ = 0;
  bool hasSpare_ = false;
};

double mirrorIntoUnit(double u) {
  const double t = u - 2 * std::floor(u / 2);  // in [0, 2)
  return t <= 1 ? t : 2 - t;
}

// The strategy parameters for a population size (tutorial, 2016 version, section A with
// the default recombination weights): all lambda samples get a weight, the better half a
// positive one (the mean moves towards them) and the worse half a negative one ("active"
// CMA: the covariance shrinks along the steps that did worst). For the mesh quality the
// worst steps are mostly those onto invalid meshes, so the distribution learns the edges
// of the narrow valid region instead of only its good directions.
struct StrategyParameters {
  int lambda, mu;
  Eigen::VectorXd weights;  // lambda of them, decreasing; the first mu sum to 1
  double mueff, cc, cs, c1, cmu, damps, chiN;

  StrategyParameters(int n, int populationSize) : lambda(populationSize), mu(populationSize / 2) {
    weights.resize(lambda);
    for (int i = 0; i < lambda; ++i) weights[i] = std::log((lambda + 1) / 2.0) - std::log(i + 1.0);
    const Eigen::VectorXd positive = weights.head(mu);
    const Eigen::VectorXd negative = weights.tail(lambda - mu);  // <= 0
    mueff = positive.sum() * positive.sum() / positive.squaredNorm();
    const double mueffNegative = negative.sum() * negative.sum() / negative.squaredNorm();
    cc = (4 + mueff / n) / (n + 4 + 2 * mueff / n);
    cs = (mueff + 2) / (n + mueff + 5);
    c1 = 2 / ((n + 1.3) * (n + 1.3) + mueff);
    cmu = std::min(1 - c1, 2 * (mueff - 2 + 1 / mueff) / ((n + 2) * (n + 2) + mueff));
    damps = 1 + 2 * std::max(0.0, std::sqrt((mueff - 1) / (n + 1)) - 1) + cs;
    chiN = std::sqrt(n) * (1 - 1.0 / (4 * n) + 1.0 / (21.0 * n * n));
    // Scale of the negative weights: the smallest of the tutorial's three bounds, the
    // last of which keeps C positive definite.
    const double negativeScale = std::min({1 + c1 / cmu, 1 + 2 * mueffNegative / (mueff + 2),
                                           (1 - c1 - cmu) / (n * cmu)});
    weights.head(mu) /= positive.sum();
    if (lambda > mu) weights.tail(lambda - mu) *= negativeScale / -negative.sum();
  }
};

// Why a start ends (tutorial, appendix B.3), in unit-cube lengths.
constexpr double tolX = 1e-7;       // every standard deviation below this
constexpr double tolFun = 1e-9;     // recent best values and the generation all this close
                                   // (Q differences this small are meaningless)
constexpr double maxCondition = 1e14;
// Initial steps. Local: a tenth of the box; measured on the tutorials (budget 300, seed
// 1), a step of 0.3 from SIRT's start put 296 of 300 samples on invalid meshes and never
// improved on the start, 0.1 found Q 0.565. Global: a third of the box, all of it in reach.
constexpr double localSigma = 0.1;
constexpr double globalSigma = 0.3;
// The pattern search's first steps (unit-cube lengths), for the last share of the budget:
// from the LS89 study's best points at 800 of 1000 evaluations, 0.005, 0.01 and 0.02
// gained alike (docs/optimization.md).
constexpr double patternSearchStep = 0.01;

// Whether `count` more evaluations fit before the last `reserve` (none kept: always).
bool fits(const EvaluationLog& log, long count, long reserve) {
  return reserve == 0 || log.remaining() - reserve >= count;
}

// A start whose whole population scores the same this many generations in a row is on a
// plateau (for the mesh quality: every mesh invalid) and ends.
constexpr int plateauGenerations = 3;

// One start: a search distribution, run until it converges, stagnates or the log ends.
class CmaEsStart {
 public:
  CmaEsStart(int n, int populationSize, Eigen::VectorXd mean, double sigma)
      : n_(n), p_(n, populationSize), mean_(std::move(mean)), sigma_(sigma),
        C_(Eigen::MatrixXd::Identity(n, n)), B_(C_), D_(Eigen::VectorXd::Ones(n)),
        pc_(Eigen::VectorXd::Zero(n)), ps_(Eigen::VectorXd::Zero(n)) {}

  // Runs until it converges or stagnates, the log is finished, or (reserve > 0) a whole
  // population would eat into the last `reserve` evaluations.
  void run(EvaluationLog& log, StandardNormal& normal, long reserve) {
    const int historyLength = 10 + static_cast<int>(std::ceil(30.0 * n_ / p_.lambda));
    std::vector<double> recentBest;
    int flatGenerations = 0;
    for (int generation = 0; !log.finished() && fits(log, p_.lambda, reserve); ++generation) {
      Eigen::MatrixXd y(n_, p_.lambda);  // the steps B D z, one per column
      std::vector<double> zLength(p_.lambda);  // |z|: a step's length in C's own metric
      std::vector<Eigen::VectorXd> unitPoints(p_.lambda);
      for (int k = 0; k < p_.lambda; ++k) {
        Eigen::VectorXd z(n_);
        for (int i = 0; i < n_; ++i) z[i] = normal();
        zLength[k] = z.norm();
        y.col(k) = B_ * D_.asDiagonal() * z;
        unitPoints[k] = (mean_ + sigma_ * y.col(k)).unaryExpr(&mirrorIntoUnit);
      }
      const std::vector<double> values = log.evaluate(unitPoints);
      if (static_cast<int>(values.size()) < p_.lambda) return;  // budget used or stopped

      // Best first; equal values (invalid meshes all score the same) rank the shorter step
      // first, so a population that lands mostly on a plateau pulls the mean back and
      // shrinks the step instead of drifting at random across it.
      std::vector<int> order(p_.lambda);
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        if (values[a] != values[b]) return values[a] > values[b];
        return zLength[a] < zLength[b];
      });
      update(y, order, generation);

      recentBest.push_back(values[order[0]]);
      flatGenerations = values[order[0]] == values[order.back()] ? flatGenerations + 1 : 0;
      if (flatGenerations >= plateauGenerations) return;
      if (converged(recentBest, historyLength, values[order[0]] - values[order.back()])) return;
    }
  }

 private:
  void update(const Eigen::MatrixXd& y, const std::vector<int>& order, int generation) {
    Eigen::VectorXd yMean = Eigen::VectorXd::Zero(n_);
    for (int i = 0; i < p_.mu; ++i) yMean += p_.weights[i] * y.col(order[i]);
    mean_ += sigma_ * yMean;

    // C^(-1/2) yMean = B D^-1 B^T yMean
    const Eigen::VectorXd whitened = B_ * (B_.transpose() * yMean).cwiseQuotient(D_);
    ps_ = (1 - p_.cs) * ps_ + std::sqrt(p_.cs * (2 - p_.cs) * p_.mueff) * whitened;
    const double psNorm = ps_.norm();
    const bool hsig = psNorm / std::sqrt(1 - std::pow(1 - p_.cs, 2.0 * (generation + 1))) / p_.chiN <
                      1.4 + 2.0 / (n_ + 1);
    pc_ = (1 - p_.cc) * pc_ + (hsig ? std::sqrt(p_.cc * (2 - p_.cc) * p_.mueff) : 0.0) * yMean;

    // Rank-mu with every sample; a negative weight's step is rescaled to the length
    // sqrt(n) in C's metric, so an unusually long bad step cannot remove too much variance.
    Eigen::MatrixXd rankMu = Eigen::MatrixXd::Zero(n_, n_);
    for (int i = 0; i < p_.lambda; ++i) {
      const Eigen::VectorXd& step = y.col(order[i]);
      double weight = p_.weights[i];
      if (weight < 0) {
        const double whitenedLength2 = (B_.transpose() * step).cwiseQuotient(D_).squaredNorm();
        weight *= n_ / std::max(whitenedLength2, 1e-300);
      }
      rankMu += weight * step * step.transpose();
    }
    const double lostVariance = hsig ? 0.0 : p_.cc * (2 - p_.cc);
    C_ = (1 - p_.c1 - p_.cmu * p_.weights.sum()) * C_ + p_.c1 * (pc_ * pc_.transpose() + lostVariance * C_) +
         p_.cmu * rankMu;
    sigma_ *= std::exp(p_.cs / p_.damps * (psNorm / p_.chiN - 1));

    C_ = C_.selfadjointView<Eigen::Upper>();  // keep it exactly symmetric
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(C_);
    B_ = eigen.eigenvectors();
    D_ = eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  }

  bool converged(const std::vector<double>& recentBest, int historyLength, double generationRange) const {
    if (sigma_ * C_.diagonal().cwiseSqrt().maxCoeff() < tolX) return true;
    if (D_.minCoeff() <= 0 || (D_.maxCoeff() / D_.minCoeff()) * (D_.maxCoeff() / D_.minCoeff()) > maxCondition)
      return true;
    if (static_cast<int>(recentBest.size()) < historyLength) return false;
    const auto [low, high] = std::minmax_element(recentBest.end() - historyLength, recentBest.end());
    return *high - *low < tolFun && generationRange < tolFun;
  }

  int n_;
  StrategyParameters p_;
  Eigen::VectorXd mean_;
  double sigma_;
  Eigen::MatrixXd C_, B_;
  Eigen::VectorXd D_;
  Eigen::VectorXd pc_, ps_;
};

}  // namespace

int runCmaEs(EvaluationLog& log) {
  const BoxProblem& problem = log.problem();
  const int n = problem.dimension();
  StandardNormal normal(derivedSeed(log.options().seed, 0));
  int populationSize = 4 + static_cast<int>(std::floor(3 * std::log(n)));
  int starts = 0;
  // Kept for the pattern search, which only polishes what CMA-ES found: the start and the
  // first population always go to CMA-ES (so even a tiny budget depends on the seed).
  const long budget = log.options().budget;
  const long reserve = std::clamp(std::lround(log.options().patternSearchShare * static_cast<double>(budget)),
                                  0L, std::max(0L, budget - 1 - populationSize));
  // The start itself first, as the NLopt methods do: the result is never worse than the
  // case's own parameters.
  const Eigen::VectorXd start = problem.toUnit(log.options().start.value_or(problem.centre()));
  if (log.evaluate({start}).empty()) return 0;
  auto runStarts = [&](long keep) {
    while (!log.finished() && fits(log, populationSize, keep)) {
      Eigen::VectorXd mean(n);
      const bool local = starts % 2 == 0;
      if (starts == 0) {
        mean = start;
      } else if (local) {
        mean = log.bestUnitPoint();
      } else {
        for (int k = 0; k < n; ++k) mean[k] = uniform01(normal.engine());
      }
      CmaEsStart(n, populationSize, mean, local ? localSigma : globalSigma).run(log, normal, keep);
      ++starts;
      populationSize *= 2;  // IPOP: a larger population sees more of a multimodal landscape
    }
  };
  runStarts(reserve);
  if (reserve > 0 && !log.finished()) {
    runPatternSearch(log, patternSearchStep);
    runStarts(0);  // what the pattern search left when it ran out of steps
  }
  return starts;
}

}  // namespace passageMesh::optimizeDetail
