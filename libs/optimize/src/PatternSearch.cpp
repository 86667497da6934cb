// Hooke & Jeeves's pattern search (J. ACM 8, 1961; as reviewed by Kolda, Lewis & Torczon,
// SIAM Review 45, 2003) in the unit cube, from the best point so far. CMA-ES hands it the
// last share of its budget (runCmaEs): the mesh quality Q is piecewise smooth with jumps
// where a rounded node count changes, rising towards those edges, so the best meshes sit
// on an edge (docs/optimization.md). A sampling method reaches such a point only by
// chance; an elitist search that steps along each coordinate, doubles a step that pays and
// halves the steps when none does, walks up the slope to the edge.
#include <algorithm>
#include <cmath>

#include "Methods.hpp"

namespace passageMesh::optimizeDetail {

namespace {

// Steps below this (unit-cube lengths) change Q less than its own rounding.
constexpr double smallestStep = 1e-7;

class PatternSearch {
 public:
  PatternSearch(EvaluationLog& log, double initialStep)
      : log_(log), best_(log.bestUnitPoint()), bestValue_(log.bestValue()),
        step_(best_.size()), unit_(best_.size()) {
    const BoxProblem& box = log.problem();
    for (int k = 0; k < box.dimension(); ++k) {
      // An integer dimension moves by whole integers, at least one (unit-cube lengths).
      unit_[k] = box.isInteger(k) ? 1 / (box.upper[k] - box.lower[k]) : 0.0;
      step_[k] = box.isInteger(k) ? unit_[k] * std::max(1.0, std::round(initialStep / unit_[k]))
                                  : initialStep;
    }
  }

  // Runs until the log is finished or no step is left to try.
  void run() {
    while (!log_.finished()) {
      const Eigen::VectorXd base = best_;
      bool improved = false;
      for (int k = 0; k < best_.size() && !log_.finished(); ++k)
        if (exploreCoordinate(k)) improved = true;
      if (improved) {
        // Pattern move: extrapolate the sweep's displacement, doubling it while it pays.
        for (;;) {
          const Eigen::VectorXd displacement = best_ - base;
          if (!tryPoint(best_ + displacement)) break;
        }
      } else if (!shrinkSteps()) {
        return;
      }
    }
  }

 private:
  // Up the coordinate in one direction, then the other if the first did not pay: each
  // successful step is followed by one twice as long.
  bool exploreCoordinate(int k) {
    for (double direction : {1.0, -1.0}) {
      double step = direction * step_[k];
      bool moved = false;
      for (;;) {
        Eigen::VectorXd trial = best_;
        trial[k] += step;
        if (!tryPoint(trial)) break;
        moved = true;
        step *= 2;
      }
      if (moved) return true;
    }
    return false;
  }

  // Evaluates a point and keeps it if it beats the best. The point is first moved to what
  // the objective would see (clipped into the box, integer dimensions rounded), in the
  // form bestUnitPoint gives, so a point equal to the best is not evaluated again.
  bool tryPoint(const Eigen::VectorXd& unitPoint) {
    if (log_.finished()) return false;
    const Eigen::VectorXd trial = log_.problem().toUnit(log_.evaluatedPoint(unitPoint));
    if (trial == best_) return false;
    const std::vector<double> value = log_.evaluate({trial});
    if (value.empty() || !(value[0] > bestValue_)) return false;
    best_ = trial;
    bestValue_ = value[0];
    return true;
  }

  // Halves every step (integer ones not below one integer); false when nothing is left.
  bool shrinkSteps() {
    bool any = false;
    for (int k = 0; k < step_.size(); ++k) {
      if (unit_[k] > 0) {
        const double halved = unit_[k] * std::floor(step_[k] / unit_[k] / 2);
        step_[k] = std::max(unit_[k], halved);
        any = any || halved >= unit_[k];
      } else {
        step_[k] /= 2;
        any = any || step_[k] >= smallestStep;
      }
    }
    return any;
  }

  EvaluationLog& log_;
  Eigen::VectorXd best_;
  double bestValue_;
  Eigen::VectorXd step_, unit_;
};

}  // namespace

void runPatternSearch(EvaluationLog& log, double initialStep) {
  if (log.bestUnitPoint().size() == 0) return;
  const long before = log.remaining();
  PatternSearch(log, initialStep).run();
  log.countPatternSearch(before - log.remaining());
}

}  // namespace passageMesh::optimizeDetail
