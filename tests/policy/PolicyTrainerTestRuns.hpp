#pragma once
// What the training-loop tests share: a small run on the toy and a fingerprint of a
// learner's weights.
#include <cmath>
#include <utility>

#include "passageMesh/policy/ActorCritic.hpp"
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

// The actor's and the critic's outputs on fixed inputs: equal exactly when the weights are.
inline std::pair<PolicyBatch, Eigen::VectorXd> fingerprint(const ActorCritic& learner, int stateSize, int actionSize) {
  PolicyBatch s(7, stateSize), a(7, actionSize);
  for (int i = 0; i < 7; ++i) {
    for (int k = 0; k < stateSize; ++k) s(i, k) = std::sin(1.0 + i * stateSize + k);
    for (int k = 0; k < actionSize; ++k) a(i, k) = std::cos(2.0 + i * actionSize + k);
  }
  return {learner.act(s), learner.value(s, a)};
}

}  // namespace passageMesh::testRuns
