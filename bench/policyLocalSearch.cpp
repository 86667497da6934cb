// policyLocalSearch: how far is a policy's one-shot action from a search's optimum, passage
// by passage, does that optimum lie with alphaCamber low or high, and how much of the gain
// is Q's roughness next to the action? (docs/policy.md "Where a search from the one-shot
// action goes".)
//   policyLocalSearch POLICY.xml SEED FIRST COUNT BUDGET [ALPHA_SPLIT]
//   policyLocalSearch POLICY.xml SEED FIRST COUNT BUDGET random RADIUS
// On PassageEnvironment's passages FIRST..FIRST+COUNT-1 of stream SEED (policyTrain's
// validation set is stream 20261202; edge radii halfLogUniform), two CMA-ES runs of BUDGET
// meshes each (iterOptimize's default method, seed 1) start from the one-shot action, both
// over all ten actions in scaled units: one with alphaCamber held at or below ALPHA_SPLIT
// (scaled; default 0.3, i.e. alphaCamber 0.65), the other at or above it; the start is the
// action clipped into each box. Prints one CSV row per passage: the one-shot reward, each
// box's best reward and its alphaCamber (in [0, 1]); an invalid mesh is -1, as in training.
// With `random RADIUS`: BUDGET actions drawn around the one-shot action instead, each
// action moved by uniform(-RADIUS, RADIUS) scaled units (clipped; the passage's random
// stream 1); the row holds the one-shot reward, the best draw (-1 if none is valid), and
// the mean and standard deviation over the valid draws. What the best draw gains at a
// radius of 0.01 (half a per cent of each range) is roughness no smooth policy can follow.
// Passages run side by side on all cores; the output does not depend on their number.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/ParallelFor.hpp"
#include "passageMesh/policy/ActionSearch.hpp"
#include "passageMesh/policy/Policy.hpp"
#include "passageMesh/policy/PolicyEnvironment.hpp"
#include "passageMesh/quality/MeshQuality.hpp"

using namespace passageMesh;

namespace {

struct BoxBest {
  double reward = 0;
  double alphaCamber = 0;  // in [0, 1]
};

BoxBest searchFrom(const EpisodeTask& task, const std::vector<double>& action, int alphaIndex, double lowAlpha,
                   double highAlpha, long budget) {
  BoxProblem box = scaledActionBox(static_cast<int>(action.size()));
  box.lower[alphaIndex] = lowAlpha;
  box.upper[alphaIndex] = highAlpha;
  std::vector<double> start = action;
  start[static_cast<std::size_t>(alphaIndex)] = std::clamp(start[static_cast<std::size_t>(alphaIndex)], lowAlpha, highAlpha);
  const PointObjective reward = [&task](const Eigen::VectorXd& x) {
    return task.reward(std::vector<double>(x.data(), x.data() + x.size()));
  };
  // One thread per search: the passages already run side by side.
  const OptimizationResult result =
      searchActions(box, start, evaluateInParallel(reward, 1), budget, 1, OptimizerOptions{}.patternSearchShare);
  return {result.bestValue, (result.best[alphaIndex] + 1) / 2};
}

struct Draws {
  double best = 0, mean = 0, deviation = 0;
};

// The draws come from the passage's random stream 1 (stream 0 drew the passage), through
// the project's uniform01 (the same numbers with every standard library).
Draws drawAround(const EpisodeTask& task, const std::vector<double>& action, double radius, long budget,
                 std::uint64_t seed, std::uint64_t passage) {
  std::mt19937_64 random = episodeRandom(seed, passage, 1);
  Draws d{invalidMeshQuality, 0, 0};
  double sum = 0, squares = 0;
  long valid = 0;
  for (long k = 0; k < budget; ++k) {
    std::vector<double> moved = action;
    for (double& x : moved) x = std::clamp(x + radius * (2 * uniform01(random) - 1), -1.0, 1.0);
    const double r = task.reward(moved);
    d.best = std::max(d.best, r);
    if (r > invalidMeshQuality) {
      sum += r;
      squares += r * r;
      ++valid;
    }
  }
  if (valid > 0) {
    d.mean = sum / static_cast<double>(valid);
    d.deviation = std::sqrt(std::max(0.0, squares / static_cast<double>(valid) - d.mean * d.mean));
  } else {
    d.mean = invalidMeshQuality;
  }
  return d;
}

}  // namespace

int main(int argc, char* argv[]) {
  return runUtility("policyLocalSearch", [&] {
    const bool random = argc >= 7 && std::string(argv[6]) == "random";
    if (argc < 6 || argc > 8 || (argc == 8) != random) {
      std::fprintf(stderr,
                   "usage: policyLocalSearch POLICY.xml SEED FIRST COUNT BUDGET [ALPHA_SPLIT | random RADIUS]\n");
      return 2;
    }
    const Policy policy = Policy::load(argv[1]);
    const std::uint64_t seed = std::stoull(argv[2]);
    const int first = std::stoi(argv[3]), count = std::stoi(argv[4]);
    const long budget = std::stol(argv[5]);
    const double split = argc == 7 ? std::stod(argv[6]) : 0.3;
    const double radius = random ? std::stod(argv[7]) : 0;
    if (first < 0 || count < 1 || budget < 1)
      throw InputError("command line: FIRST >= 0, COUNT >= 1 and BUDGET >= 1 expected, not " + std::to_string(first) +
                       ", " + std::to_string(count) + ", " + std::to_string(budget));
    if (!(split > -1 && split < 1)) throw InputError("command line: ALPHA_SPLIT in (-1, 1) expected, not " + std::string(argv[6]));
    if (random && !(radius > 0 && radius <= 2)) throw InputError("command line: RADIUS in (0, 2] expected, not " + std::string(argv[7]));
    const auto& names = MeshingParameters::names();
    const int alphaIndex = static_cast<int>(std::find(names.begin(), names.end(), "alphaCamber") - names.begin());
    const PassageEnvironment environment(EdgeRadiusDraw::halfLogUniform, policy.stateScaling());

    struct Row {
      double oneShot = 0;
      BoxBest low, high;
      Draws draws;
    };
    std::vector<Row> rows(static_cast<std::size_t>(count));
    parallelFor(count, 0, [&](int i) {
      const EpisodeTask task =
          environment.draw(seed, static_cast<std::uint64_t>(first + i), EpisodePurpose::validation);
      PolicyState state;
      std::copy(task.state.begin(), task.state.end(), state.begin());
      const PolicyAction a = policy.act(state);
      const std::vector<double> action(a.begin(), a.end());
      Row& row = rows[static_cast<std::size_t>(i)];
      row.oneShot = task.reward(action);
      if (random) {
        row.draws = drawAround(task, action, radius, budget, seed, static_cast<std::uint64_t>(first + i));
        return;
      }
      row.low = searchFrom(task, action, alphaIndex, -1.0, split, budget);
      row.high = searchFrom(task, action, alphaIndex, split, 1.0, budget);
    });
    if (random) {
      std::printf("passage,oneShotReward,bestDrawnReward,meanValidDrawnReward,deviationValidDrawnReward\n");
      for (int i = 0; i < count; ++i) {
        const Row& r = rows[static_cast<std::size_t>(i)];
        std::printf("%d,%.17g,%.17g,%.17g,%.17g\n", first + i, r.oneShot, r.draws.best, r.draws.mean, r.draws.deviation);
      }
      return 0;
    }
    std::printf("passage,oneShotReward,lowBestReward,lowAlphaCamber,highBestReward,highAlphaCamber\n");
    for (int i = 0; i < count; ++i) {
      const Row& r = rows[static_cast<std::size_t>(i)];
      std::printf("%d,%.17g,%.17g,%.6f,%.17g,%.6f\n", first + i, r.oneShot, r.low.reward, r.low.alphaCamber,
                  r.high.reward, r.high.alphaCamber);
    }
    return 0;
  });
}
