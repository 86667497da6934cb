#pragma once
// What the training-loop tests share: a small run on the toy and a fingerprint of a
// learner's weights.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "../TestFiles.hpp"
#include "passageMesh/policy/ActorCritic.hpp"
#include "passageMesh/policy/Policy.hpp"
#include "passageMesh/policy/PolicyEnvironment.hpp"
#include "passageMesh/policy/PolicyTrainer.hpp"
#include "passageMesh/policy/PolicyTrainOptions.hpp"

namespace passageMesh::testRuns {

inline PolicyTrainOptions smallRun(long episodes) {
  PolicyTrainOptions o;
  o.episodes = episodes;
  o.batchEpisodes = 16;
  o.minibatch = 20;
  o.hidden = {16, 16};
  o.learningRates = {1e-3, 1e-3};
  o.validationEvery = 100;
  o.validationPassages = 5;
  o.checkpointEvery = 64;
  o.logEvery = 50;
  o.noiseStartEpisodes = 40;
  o.seed = 11;
  o.threads = 1;
  return o;
}

// Seven fixed states.
inline PolicyBatch fingerprintStates(int stateSize) {
  PolicyBatch s(7, stateSize);
  for (int i = 0; i < 7; ++i)
    for (int k = 0; k < stateSize; ++k) s(i, k) = std::sin(1.0 + i * stateSize + k);
  return s;
}

// The actor's and the critic's outputs on fixed inputs: equal exactly when the weights are.
inline std::pair<PolicyBatch, Eigen::VectorXd> fingerprint(const ActorCritic& learner, int stateSize, int actionSize) {
  const PolicyBatch s = fingerprintStates(stateSize);
  PolicyBatch a(7, actionSize);
  for (int i = 0; i < 7; ++i)
    for (int k = 0; k < actionSize; ++k) a(i, k) = std::cos(2.0 + i * actionSize + k);
  return {learner.act(s), learner.value(s, a)};
}

// Runs `trainer` to its first checkpoint, writes it to `file` and stops there, as if the
// tool were killed right after it; returns whether the run stopped (it should).
inline bool runToFirstCheckpoint(PolicyTrainer& trainer, const std::filesystem::path& file) {
  std::atomic<bool> stop{false};
  PolicyTrainer::Events events;
  events.checkpointDue = [&](const PolicyTrainer& t) {
    t.saveCheckpoint(file);
    stop = true;
  };
  return !trainer.run(&stop, events);
}

// The mean reward of the learner's policy on the validation passages of `options`, through
// the policy files as policyMesh reads them (written to the temporary folder `folder`).
inline double meanRewardThroughPolicyFiles(const ActorCritic& learner, const PolicyEnvironment& environment,
                                           const PolicyTrainOptions& options, const std::string& folder) {
  const auto dir = testData::tempFolder(folder);
  std::filesystem::create_directories(dir);
  writePolicyFiles(dir / "policy.xml", learner, policyStateScaling(BladeParameterRange::readDefault()),
                   PolicyProvenance{});
  const Policy policy = Policy::load(dir / "policy.xml");
  double sum = 0;
  for (int i = 0; i < options.validationPassages; ++i) {
    const EpisodeTask task =
        environment.draw(options.validationSeed, static_cast<std::uint64_t>(i), EpisodePurpose::validation);
    PolicyState state;
    std::copy(task.state.begin(), task.state.end(), state.begin());
    const PolicyAction action = policy.act(state);
    sum += task.reward(std::vector<double>(action.begin(), action.end()));
  }
  return sum / options.validationPassages;
}

}  // namespace passageMesh::testRuns
