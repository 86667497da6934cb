#include "passageMesh/blade/BladeFit.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <chrono>
#include <numeric>
#include <cmath>

#include "passageMesh/blade/BladeProjection.hpp"
#include "passageMesh/blade/BladeShape.hpp"
#include "passageMesh/core/ParallelFor.hpp"

namespace passageMesh {

namespace {

constexpr int nP = BladeParameters::size;
using Jet = ceres::Jet<double, nP>;
using RowJacobian = Eigen::Matrix<double, 2, nP>;

// Signed distances of the points from the profile, one residual per point. The foot
// points are found afresh at each evaluation, so the Jacobian of a distance is
// -n . dC/dp at the foot point (the foot point's own motion is tangential).
//
// Two more residuals tie the profile's end points (leading and trailing edge) to the
// polygon of the points. Without them a blade with sharp edges can grow zero-thickness
// tails beyond the data that no point-to-curve distance sees; they are weighted like all
// the points together. Two last residuals weakly pull the thickness next to each edge
// towards equal upper and lower values (see Evaluate).
class ProfileDistanceCost final : public ceres::CostFunction {
 public:
  // Small enough not to bias a blade the parametrization represents exactly (recovery
  // test: 0.05 cost ~10 % of the recoveries), large enough to break ties on round edges.
  static constexpr double symmetryWeight = 0.001;
  // With `power` p > 2 each distance r enters as |r|^(p/2) / scale^(p/2-1), so the sum of
  // squares becomes the sum of |r|^p, which weighs the largest deviations more.
  ProfileDistanceCost(const std::vector<Eigen::Vector2d>& points, double power, double scale)
      : points_(points), edgeWeight_(std::sqrt(static_cast<double>(points.size()))),
        power_(power), scale_(scale) {
    set_num_residuals(static_cast<int>(points.size()) + 4);
    mutable_parameter_block_sizes()->push_back(nP);
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const double* p = parameters[0];
    for (int k = 0; k < nP; ++k)
      if (!std::isfinite(p[k])) return false;
    const BladeShape shape(BladeParameters::fromArray(p));
    const BladeProjector projector(shape, 64);

    std::array<RowJacobian, sideControlCount> dLower, dUpper;
    if (jacobians && jacobians[0]) {
      controlPointJacobians(p, dLower, dUpper);
      // An edge control point sits at sqrt(h * radius / 3) from the edge: its derivative
      // is unbounded where h * radius -> 0. Such a point is rejected as a step, not used.
      for (int c = 0; c < sideControlCount; ++c)
        if (!dLower[c].allFinite() || !dUpper[c].allFinite()) return false;
    }

    for (std::size_t i = 0; i < points_.size(); ++i) {
      const FootPoint foot = projector.project(points_[i]);
      const double r = foot.signedDistance;
      if (!std::isfinite(r)) return false;
      const double magnitude = std::abs(r) / scale_;
      const double half = 0.5 * power_;
      residuals[i] = (r < 0 ? -scale_ : scale_) * std::pow(magnitude, half);
      const double chain = half * std::pow(magnitude, half - 1.0);  // d residual / d r
      if (!jacobians || !jacobians[0]) continue;
      // Unit direction of the residual: (q - C)/|q - C| with the residual's sign, or the
      // outward normal when the point lies on the curve.
      const Eigen::Vector2d gap = points_[i] - foot.point;
      const double distance = gap.norm();
      const Eigen::Vector2d direction =
          distance > 1e-14 ? Eigen::Vector2d(gap / distance * (foot.signedDistance < 0 ? -1.0 : 1.0))
                           : shape.outwardNormal(foot.side, foot.u);
      const CubicBasis b = cubicBasis(sideControlCount, foot.u);
      const auto& d = foot.side == BladeSide::lower ? dLower : dUpper;
      RowJacobian dC = d[b.first] * b.value[0];
      for (int k = 1; k < 4; ++k) dC += d[b.first + k] * b.value[k];
      Eigen::Map<Eigen::Matrix<double, 1, nP>> row(jacobians[0] + i * nP);
      row = -chain * direction.transpose() * dC;
    }
    const std::size_t n = points_.size();
    const int edgeControlPoint[2] = {0, sideControlCount - 1};
    for (int e = 0; e < 2; ++e) {
      const Eigen::Vector2d edge = shape.sideControlPoints(BladeSide::lower)[edgeControlPoint[e]];
      const Eigen::Vector2d gap = edge - nearestOnPolygon(edge);
      const double distance = gap.norm();
      residuals[n + e] = edgeWeight_ * distance;
      if (!jacobians || !jacobians[0]) continue;
      Eigen::Map<Eigen::Matrix<double, 1, nP>> row(jacobians[0] + (n + e) * nP);
      if (distance > 1e-14)
        row = edgeWeight_ * (gap / distance).transpose() * dLower[edgeControlPoint[e]];
      else
        row.setZero();
    }
    // On a round edge the edge point could slide along the circle with the thickness
    // taking up the difference; a weak pull towards equal upper and lower thickness next
    // to each edge puts it where the camber line bisects the edge, as a designer would.
    const int pairs[2][2] = {{10, 16}, {15, 21}};
    for (int e = 0; e < 2; ++e) {
      residuals[n + 2 + e] = symmetryWeight * (p[pairs[e][0]] - p[pairs[e][1]]);
      if (!jacobians || !jacobians[0]) continue;
      Eigen::Map<Eigen::Matrix<double, 1, nP>> row(jacobians[0] + (n + 2 + e) * nP);
      row.setZero();
      row[pairs[e][0]] = symmetryWeight;
      row[pairs[e][1]] = -symmetryWeight;
    }
    return true;
  }

 private:
  static void controlPointJacobians(const double* p,
                                    std::array<RowJacobian, sideControlCount>& lower,
                                    std::array<RowJacobian, sideControlCount>& upper) {
    std::array<Jet, nP> jets;
    for (int k = 0; k < nP; ++k) jets[k] = Jet(p[k], k);
    const BladeControlPoints<Jet> cp = bladeControlPoints<Jet>(jets.data());
    for (int c = 0; c < sideControlCount; ++c)
      for (int xy = 0; xy < 2; ++xy) {
        lower[c].row(xy) = cp.lower[c][xy].v.transpose();
        upper[c].row(xy) = cp.upper[c][xy].v.transpose();
      }
  }

  Eigen::Vector2d nearestOnPolygon(const Eigen::Vector2d& q) const {
    Eigen::Vector2d best = points_[0];
    double bestDistance = std::numeric_limits<double>::max();
    for (std::size_t k = 0; k < points_.size(); ++k) {
      const Eigen::Vector2d& a = points_[k];
      const Eigen::Vector2d& b = points_[(k + 1) % points_.size()];
      const double t = std::clamp((q - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      const Eigen::Vector2d c = a + t * (b - a);
      if ((q - c).squaredNorm() < bestDistance) {
        bestDistance = (q - c).squaredNorm();
        best = c;
      }
    }
    return best;
  }

  const std::vector<Eigen::Vector2d>& points_;
  double edgeWeight_;
  double power_;
  double scale_;
};

struct Start {
  std::array<double, nP> values;
  double cost;
  int iterations;
};

Start solveFrom(const std::vector<Eigen::Vector2d>& points, const BladeParameters& guess,
                int maxIterations, double power, double scale) {
  Start s{guess.toArray(), 0, 0};
  auto* cost = new ProfileDistanceCost(points, power, scale);
  ceres::Problem problem;  // owns `cost`
  problem.AddResidualBlock(cost, nullptr, s.values.data());
  // A start whose Jacobian is not defined (an edge point exactly on the edge tangent) is
  // dropped here rather than handed to Ceres, which would only report the failure.
  {
    std::vector<double> residuals(cost->num_residuals()), jacobian(cost->num_residuals() * nP);
    const double* parameters[] = {s.values.data()};
    double* jacobians[] = {jacobian.data()};
    if (!cost->Evaluate(parameters, residuals.data(), jacobians)) {
      s.cost = std::numeric_limits<double>::infinity();
      return s;
    }
  }
  // Bounds keep the parametrization defined: positive chord, handles and radii, and
  // non-negative thickness (negative thickness is an invalid blade).
  problem.SetParameterLowerBound(s.values.data(), 2, 0.2 * guess.chord);
  for (int k : {6, 7}) {
    problem.SetParameterLowerBound(s.values.data(), k, 0.02);
    problem.SetParameterUpperBound(s.values.data(), k, 2.0);
  }
  for (int k : {8, 9}) {
    problem.SetParameterLowerBound(s.values.data(), k, 1e-5);
    problem.SetParameterUpperBound(s.values.data(), k, 1.0);
  }
  for (int k = 10; k < nP; ++k) problem.SetParameterLowerBound(s.values.data(), k, 0.0);
  // Camber end directions pointing downstream keep the camber line single-valued in x.
  for (int k : {4, 5}) {
    problem.SetParameterLowerBound(s.values.data(), k, -88.0);
    problem.SetParameterUpperBound(s.values.data(), k, 88.0);
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = maxIterations;
  options.function_tolerance = 1e-15;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-14;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  s.cost = summary.final_cost;
  s.iterations = static_cast<int>(summary.iterations.size());
  return s;
}

// One start: solved in a frame with the start's leading edge at the origin and unit chord,
// so that every parameter is of order one; lengths are mapped back afterwards.
struct Candidate {
  BladeParameters parameters;
  double cost = 0;  // [m^2]
  bool valid = false;
};

Candidate solveStart(const std::vector<Eigen::Vector2d>& points, const BladeParameters& g,
                     int maxIterations, int& iterations, double power = 2,
                     double scaleInChords = 1) {
  const Eigen::Vector2d origin(g.xLe, g.yLe);
  const double scale = g.chord;
  std::vector<Eigen::Vector2d> local(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) local[k] = (points[k] - origin) / scale;
  BladeParameters trial = g;
  trial.xLe = trial.yLe = 0;
  trial.chord = 1;
  const Start solved = solveFrom(local, trial, maxIterations, power, scaleInChords);
  iterations += solved.iterations;
  Candidate c;
  c.parameters = BladeParameters::fromArray(solved.values);
  c.parameters.xLe = origin.x() + scale * c.parameters.xLe;
  c.parameters.yLe = origin.y() + scale * c.parameters.yLe;
  c.parameters.chord *= scale;
  c.cost = solved.cost * scale * scale;
  return c;
}

bool better(const Candidate& a, const Candidate& b) {
  return a.valid != b.valid ? a.valid : a.cost < b.cost;
}

// One round of the multi-start search: every guess fitted coarsely (few iterations on a
// subsample), the best `refinedStarts` of them converged on a larger subsample, the best
// valid result kept.
Candidate searchRound(const std::vector<Eigen::Vector2d>& subsample,
                      const std::vector<Eigen::Vector2d>& refineSample,
                      const std::vector<BladeParameters>& guesses,
                      const BladeFitOptions& options, int& iterations) {
  const int coarseCount = static_cast<int>(guesses.size());
  std::vector<double> coarseCost(coarseCount);
  std::vector<int> coarseIterations(coarseCount, 0);
  parallelFor(coarseCount, options.threads, [&](int s) {
    coarseCost[s] = solveStart(subsample, guesses[s], options.coarseIterations,
                               coarseIterations[s]).cost;
  });
  std::vector<int> order(coarseCount);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return coarseCost[a] < coarseCost[b]; });

  const int refined = std::min(options.refinedStarts, coarseCount);
  std::vector<Candidate> candidates(refined);
  std::vector<int> refinedIterations(refined, 0);
  parallelFor(refined, options.threads, [&](int s) {
    candidates[s] = solveStart(refineSample, guesses[order[s]], options.maxIterations,
                               refinedIterations[s]);
    candidates[s].valid = checkBladeValidity(BladeShape(candidates[s].parameters)).valid;
  });
  Candidate best = candidates[0];
  for (const Candidate& c : candidates)
    if (better(c, best)) best = c;
  iterations += std::accumulate(coarseIterations.begin(), coarseIterations.end(), 0) +
                std::accumulate(refinedIterations.begin(), refinedIterations.end(), 0);

  return best;
}

}  // namespace

BladeFitResult fitBlade(const std::vector<Eigen::Vector2d>& points,
                        const BladeFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  BladeFitResult result;
  result.initialGuess = guessBladeParameters(points);

  // Where the edge points sit on round edges, and so the camber angles, is the least
  // determined part of the shape: the search tries a grid of edge angles around the guess.
  // While the best fit misses the target deviation, further rounds try the grid shifted
  // by half its spacing.
  auto everyNth = [&](int count) {
    std::vector<Eigen::Vector2d> sample;
    const std::size_t stride = std::max<std::size_t>(1, points.size() / std::max(count, 1));
    for (std::size_t k = 0; k < points.size(); k += stride) sample.push_back(points[k]);
    return sample;
  };
  const auto subsample = everyNth(options.coarsePoints);
  const auto refineSample = everyNth(options.refinePoints);
  const double stagger = result.initialGuess.stagger;
  const double shifts[][2] = {{0, 0}, {0.5, 0.5}, {0.5, 0}, {0, 0.5}};
  const int rounds = std::clamp(options.maxRounds, 1, 4);

  Candidate best;
  double bestMax = std::numeric_limits<double>::infinity();
  for (int round = 0; round < rounds; ++round) {
    std::vector<BladeParameters> guesses;
    if (round == 0) {
      guesses.push_back(result.initialGuess);
      for (const auto& extra : options.extraStarts) guesses.push_back(extra);
    }
    for (double le : options.leadingEdgeAngles)
      for (double te : options.trailingEdgeAngles)
        guesses.push_back(guessBladeParameters(
            points, stagger + le + shifts[round][0] * options.gridSpacing,
            stagger + te + shifts[round][1] * options.gridSpacing));
    result.starts += static_cast<int>(guesses.size());
    ++result.rounds;
    const Candidate c =
        searchRound(subsample, refineSample, guesses, options, result.iterations);
    const double max = deviationFromProfile(BladeShape(c.parameters), points).max;
    if (round == 0 || (c.valid && !best.valid) || (c.valid == best.valid && max < bestMax)) {
      best = c;
      bestMax = max;
    }
    if (best.valid && bestMax <= options.targetMaxDeviation * best.parameters.chord) break;
  }

  // Polish the winner on all points with a higher power of the distances, which trades a
  // little of the mean deviation for a lower maximum.
  const double rms = std::sqrt(2 * best.cost / static_cast<double>(refineSample.size()));
  if (options.finalPower > 2 && std::isfinite(rms) && rms > 0) {
    Candidate c = solveStart(points, best.parameters, options.maxIterations, result.iterations,
                             options.finalPower, rms / best.parameters.chord);
    c.valid = checkBladeValidity(BladeShape(c.parameters)).valid;
    if (c.valid || !best.valid) best = c;
  }
  result.parameters = best.parameters;

  const BladeShape shape(result.parameters);
  const Deviation d = deviationFromProfile(shape, points);
  result.meanDeviation = d.mean;
  result.maxDeviation = d.max;
  result.maxDeviationPoint = d.maxIndex;
  result.validity = checkBladeValidity(shape);
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace passageMesh
