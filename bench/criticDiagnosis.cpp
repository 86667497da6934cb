// criticDiagnosis: what a training's critic believes against the mesher's true Q, on the
// validation passages (docs/policy-history.md "Where the one-shot Q is lost").
//   criticDiagnosis CASE SEED PASSAGES slices HALFWIDTH POINTS OUT.csv
//   criticDiagnosis CASE SEED PASSAGES cmaes BUDGET
// CASE is a policyTrain case (its system/policyTrainDict.xml and policy/checkpoint.pt);
// passages are episodes 0..PASSAGES-1 of stream SEED (20261202: the validation set).
// slices: along each action axis through the actor's action, POINTS actions spread over
// +-HALFWIDTH (scaled units, clipped to [-1, 1]), the critic's expected reward and the
// true reward of each; one row per action to OUT.csv, and per axis the mean gain the axis
// offers over the actor's action (0 for a passage whose actor mesh is invalid) and the critic's error near and far from it.
// cmaes: CMA-ES (iterOptimize's default, from the defaults, seed 1) with BUDGET meshes per
// passage; prints the actor's and the search's actions, Q and the critic's belief at both.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/ParallelFor.hpp"
#include "passageMesh/policy/PolicyTrainer.hpp"
#include "PassageSearch.hpp"

using namespace passageMesh;

namespace {

std::vector<double> rowOf(const PolicyBatch& b, Eigen::Index i) {
  return std::vector<double>(b.row(i).data(), b.row(i).data() + b.cols());
}

void slices(const ActorCritic& learner, const std::vector<EpisodeTask>& tasks, int stateSize, double half,
            int points, const std::string& out) {
  const int m = learner.layout().actionSize;
  std::string csv = "passage,axis,offset,action,critic,reward\n";
  std::vector<double> gain(static_cast<std::size_t>(m), 0.0);
  std::vector<double> nearErrors, farErrors;  // |critic - Q| on valid meshes
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    const PolicyBatch s = statesOf({tasks[i]}, stateSize);
    const PolicyBatch a0 = learner.act(s);
    const int n = m * points;
    PolicyBatch states(n, s.cols()), actions(n, m);
    for (int r = 0; r < n; ++r) {
      const int k = r / points, j = r % points;
      states.row(r) = s.row(0);
      actions.row(r) = a0.row(0);
      actions(r, k) = std::clamp(a0(0, k) - half + 2 * half * j / (points - 1), -1.0, 1.0);
    }
    const Eigen::VectorXd critic = learner.value(states, actions);
    std::vector<double> reward(static_cast<std::size_t>(n));
    parallelFor(n, 0, [&](int r) { reward[static_cast<std::size_t>(r)] = tasks[i].reward(rowOf(actions, r)); });
    const double atActor = tasks[i].reward(rowOf(a0, 0));
    for (int r = 0; r < n; ++r) {
      const int k = r / points;
      const double offset = actions(r, k) - a0(0, k), q = reward[static_cast<std::size_t>(r)];
      char line[160];
      std::snprintf(line, sizeof line, "%zu,%d,%.6f,%.6f,%.9f,%.9f\n", i, k, offset, actions(r, k), critic(r), q);
      csv += line;
      if (atActor > -1) gain[static_cast<std::size_t>(k)] = std::max(gain[static_cast<std::size_t>(k)], q - atActor);
      if (q <= -1) continue;
      const double e = std::abs(critic(r) - q);
      if (std::abs(offset) <= 0.05) nearErrors.push_back(e);
      if (std::abs(offset) >= 0.2) farErrors.push_back(e);
    }
  }
  writeFileAtomically(out, csv);
  std::printf("mean best gain along one axis over the actor's action (over all passages; one whose actor mesh "
              "is invalid counts 0):");
  for (int k = 0; k < m; ++k)
    std::printf(" %s %.4f", MeshingParameters::names()[static_cast<std::size_t>(k)].c_str(),
                gain[static_cast<std::size_t>(k)] / static_cast<double>(tasks.size()));
  // The median: where the validity network is unsure, the expected reward sits far below a
  // valid mesh's Q, and a mean would show those few passages only.
  const RewardSummary nearSummary = summarizeRewards(nearErrors), farSummary = summarizeRewards(farErrors);
  std::printf("\ncritic's median |expected reward - Q| on valid meshes: within 0.05 of the actor's action %.4f "
              "(%d meshes), 0.2 or more away %.4f (%d)\n  wrote %s\n", nearSummary.median, nearSummary.count,
              farSummary.median, farSummary.count, out.c_str());
}

void againstCmaes(const ActorCritic& learner, const std::vector<EpisodeTask>& tasks, const PolicyEnvironment& env,
                  long budget) {
  const int m = learner.layout().actionSize;
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    const PolicyBatch s = statesOf({tasks[i]}, env.stateSize());
    const PolicyBatch a0 = learner.act(s);
    const EpisodeTask& task = tasks[i];
    const OptimizationResult r = bench::searchPassage(task, env.defaultAction(), budget);
    PolicyBatch best(1, m);
    for (int k = 0; k < m; ++k) best(0, k) = r.best[k];
    std::printf("passage %zu: Q actor %.4f, CMA-ES %.4f; critic at the actor's action %.4f, at CMA-ES's %.4f; "
                "actions (actor / CMA-ES):", i, task.reward(rowOf(a0, 0)), r.bestValue, learner.value(s, a0)(0),
                learner.value(s, best)(0));
    for (int k = 0; k < m; ++k)
      std::printf(" %s %+.2f / %+.2f", MeshingParameters::names()[static_cast<std::size_t>(k)].c_str(), a0(0, k),
                  best(0, k));
    std::printf("\n");
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char* argv[]) {
  return runUtility("criticDiagnosis", [&] {
    const std::string mode = argc > 4 ? argv[4] : "";
    if (!((mode == "slices" && argc == 8) || (mode == "cmaes" && argc == 6))) {
      std::fprintf(stderr, "usage: criticDiagnosis CASE SEED PASSAGES slices HALFWIDTH POINTS OUT.csv\n"
                           "       criticDiagnosis CASE SEED PASSAGES cmaes BUDGET\n");
      return 2;
    }
    const std::filesystem::path caseDir = argv[1];
    const PolicyTrainOptions options = readPolicyTrainDict(caseDir / "system" / "policyTrainDict.xml");
    const PassageEnvironment environment = options.passageEnvironment();
    ThreadRollouts rollouts(1);
    PolicyTrainer trainer(options, environment, rollouts);
    trainer.resume(caseDir / "policy" / "checkpoint.pt");
    std::printf("criticDiagnosis: %s at episode %ld\n", caseDir.c_str(), trainer.episode());
    std::vector<EpisodeTask> tasks;
    for (int i = 0; i < std::stoi(argv[3]); ++i)
      tasks.push_back(environment.draw(std::stoull(argv[2]), static_cast<std::uint64_t>(i), EpisodePurpose::validation));
    if (mode == "slices")
      slices(trainer.learner(), tasks, environment.stateSize(), std::stod(argv[5]), std::stoi(argv[6]), argv[7]);
    else
      againstCmaes(trainer.learner(), tasks, environment, std::stol(argv[5]));
    return 0;
  });
}
