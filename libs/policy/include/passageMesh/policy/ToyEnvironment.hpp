#pragma once
// A cheap stand-in for the passage environment with a known optimal policy: the learning
// tests and the learner benchmark train on it.
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "passageMesh/policy/ActorCritic.hpp"
#include "passageMesh/policy/PolicyEnvironment.hpp"

namespace passageMesh {

// A cheap problem of the same sizes with a known optimum, for tests and benchmarks: states
// uniform in [-1, 1]^stateSize, optimum x*(s) = 0.8 tanh(W s) with a fixed random W
// (rows scaled to unit length), reward 1 - RMS(a - x*(s)): a cone, peaked like Q, whose
// pull towards the optimum does not fade near it as a quadratic's would. With a finite
// `cliff`, an action with a_0 > x*_0 + cliff gets -1, as an invalid mesh does: the optimum
// sits that close to a region of failures, as the mesher's best often does.
class ToyEnvironment final : public PolicyEnvironment {
 public:
  ToyEnvironment(int stateSize, int actionSize, std::uint64_t seed,
                 double cliff = std::numeric_limits<double>::infinity());
  int stateSize() const override { return stateSize_; }
  int actionSize() const override { return actionSize_; }
  EpisodeTask draw(std::uint64_t seed, std::uint64_t episode, EpisodePurpose purpose) const override;
  std::vector<double> optimum(const std::vector<double>& state) const;
  // The RMS distance of the noise-free actor's actions from the optimum (scaled units)
  // over `count` states of stream `seed`.
  double actionError(const ActorCritic& learner, std::uint64_t seed, int count) const;

 private:
  int stateSize_, actionSize_;
  double cliff_;
  std::shared_ptr<const std::vector<double>> weights_;  // actionSize x stateSize, row-major
};

}  // namespace passageMesh
