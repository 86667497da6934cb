// policySensitivity: is a policy's one-shot action off the best place on average, one
// meshing parameter at a time? (docs/policy.md "Is the policy centred?".)
//   policySensitivity POLICY.xml SEED COUNT [STEP ...]
// On PassageEnvironment's passages 0..COUNT-1 of stream SEED (policyTrain's validation set
// is stream 20261202; edge radii halfLogUniform, as policyTrain draws them), each action of
// the policy's one-shot action is moved alone by each STEP (scaled units, the action
// clipped to [-1, 1]; default -0.3 -0.2 -0.1 0.1 0.2 0.3) and the passage meshed again.
// Prints per action: the mean action, how often it sits at a bound (|a| >= 0.98), and the
// mean reward change of each step paired over the passages, +- its standard error (an
// invalid mesh counts -1, as in training). A step that raises the mean by several standard
// errors is a bias the training left; none means the policy is centred and what it loses
// is passage by passage. Last, the mean over passages of the best of all these moves (an
// upper bound on what one-coordinate corrections could give).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/ParallelFor.hpp"
#include "passageMesh/policy/Policy.hpp"
#include "passageMesh/policy/PolicyEnvironment.hpp"
#include "passageMesh/quality/MeshQuality.hpp"

using namespace passageMesh;

int main(int argc, char* argv[]) {
  return runUtility("policySensitivity", [&] {
    if (argc < 4) {
      std::fprintf(stderr, "usage: policySensitivity POLICY.xml SEED COUNT [STEP ...]\n");
      return 2;
    }
    const Policy policy = Policy::load(argv[1]);
    const std::uint64_t seed = std::stoull(argv[2]);
    const int count = std::stoi(argv[3]);
    std::vector<double> steps = {-0.3, -0.2, -0.1, 0.1, 0.2, 0.3};
    if (argc > 4) steps.assign(argc - 4, 0.0);
    for (int k = 4; k < argc; ++k) steps[static_cast<std::size_t>(k - 4)] = std::stod(argv[k]);
    if (count < 2) throw InputError("command line: COUNT must be at least 2, not " + std::to_string(count));
    const PassageEnvironment environment(EdgeRadiusDraw::halfLogUniform, policy.stateScaling());
    const int actions = policyActionSize;
    const int moves = actions * static_cast<int>(steps.size());

    struct Passage {
      std::vector<double> action;
      double reward = invalidMeshQuality;
      std::vector<double> moved;  // [action k][step d], k major
    };
    std::vector<Passage> passages(static_cast<std::size_t>(count));
    parallelFor(count, 0, [&](int i) {
      const EpisodeTask task = environment.draw(seed, static_cast<std::uint64_t>(i), EpisodePurpose::validation);
      PolicyState state;
      std::copy(task.state.begin(), task.state.end(), state.begin());
      const PolicyAction a = policy.act(state);
      Passage& p = passages[static_cast<std::size_t>(i)];
      p.action.assign(a.begin(), a.end());
      p.reward = task.reward(p.action);
      p.moved.resize(static_cast<std::size_t>(moves));
      for (int k = 0; k < actions; ++k)
        for (std::size_t d = 0; d < steps.size(); ++d) {
          std::vector<double> changed = p.action;
          auto& x = changed[static_cast<std::size_t>(k)];
          x = std::clamp(x + steps[d], -1.0, 1.0);
          // (a step that the bound cancels gives the same mesh)
          p.moved[static_cast<std::size_t>(k) * steps.size() + d] =
              x == p.action[static_cast<std::size_t>(k)] ? p.reward : task.reward(changed);
        }
    });

    double meanReward = 0, meanBestMove = 0;
    for (const Passage& p : passages) {
      meanReward += p.reward / count;
      meanBestMove += std::max(p.reward, *std::max_element(p.moved.begin(), p.moved.end())) / count;
    }
    std::printf("%s on %d passages of stream %llu: mean reward %.6f\n", argv[1], count,
                static_cast<unsigned long long>(seed), meanReward);
    std::printf("%-12s %12s %10s", "action", "mean action", "low/high");
    for (double s : steps) std::printf("  %+19.2f", s);
    std::printf("\n");
    for (int k = 0; k < actions; ++k) {
      double mean = 0;
      int low = 0, high = 0;
      for (const Passage& p : passages) {
        const double a = p.action[static_cast<std::size_t>(k)];
        mean += a / count;
        low += a <= -0.98;
        high += a >= 0.98;
      }
      std::printf("%-12s %+12.4f %5d/%-4d", MeshingParameters::names()[static_cast<std::size_t>(k)].c_str(), mean,
                  low, high);
      for (std::size_t d = 0; d < steps.size(); ++d) {
        double sum = 0, squares = 0;
        for (const Passage& p : passages) {
          const double change = p.moved[static_cast<std::size_t>(k) * steps.size() + d] - p.reward;
          sum += change;
          squares += change * change;
        }
        const double m = sum / count;
        const double se = std::sqrt(std::max(0.0, squares / count - m * m) / (count - 1));
        std::printf("  %+9.5f +- %7.5f", m, se);
      }
      std::printf("\n");
    }
    std::printf("mean over passages of the best of the %d one-action moves (or none): %.6f (%+.6f)\n", moves,
                meanBestMove, meanBestMove - meanReward);
    return 0;
  });
}
