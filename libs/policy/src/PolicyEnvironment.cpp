#include "passageMesh/policy/PolicyEnvironment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "passageMesh/blade/BladeShape.hpp"
#include "passageMesh/passage/PassageSampler.hpp"
#include "passageMesh/policy/PolicyScaling.hpp"
#include "passageMesh/quality/MeshQuality.hpp"
#include "passageMesh/workflow/MeshQualityObjective.hpp"

namespace passageMesh {

std::mt19937_64 episodeRandom(std::uint64_t seed, std::uint64_t episode, std::uint32_t stream) {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(episode),
                         static_cast<std::uint32_t>(episode >> 32), stream};
  return std::mt19937_64(sequence);
}

PolicyBatch statesOf(const std::vector<EpisodeTask>& tasks, int stateSize) {
  PolicyBatch states(static_cast<long>(tasks.size()), stateSize);
  for (std::size_t i = 0; i < tasks.size(); ++i)
    states.row(static_cast<long>(i)) = Eigen::Map<const Eigen::RowVectorXd>(tasks[i].state.data(), stateSize);
  return states;
}

RewardSummary summarizeRewards(const std::vector<double>& rewards) {
  RewardSummary s;
  s.count = static_cast<int>(rewards.size());
  if (rewards.empty()) return s;
  double sum = 0;
  for (double r : rewards) {
    sum += r;
    s.valid += r > invalidMeshQuality;
  }
  s.mean = sum / s.count;
  std::vector<double> sorted = rewards;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  s.median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  return s;
}

double standardNormal(std::mt19937_64& rng) {
  const double u1 = 1.0 - uniform01(rng);  // in (0, 1]: the logarithm stays finite
  const double u2 = uniform01(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

PassageEnvironment::PassageEnvironment(BladeParameterRange range, EdgeRadiusDraw edgeRadii,
                                       PolicyStateScaling scaling, TrainingMeshes trainingMeshes)
    : range_(std::move(range)), edgeRadii_(edgeRadii), scaling_(scaling), trainingMeshes_(trainingMeshes) {}
PassageEnvironment::PassageEnvironment(EdgeRadiusDraw edgeRadii, PolicyStateScaling scaling,
                                       TrainingMeshes trainingMeshes)
    : PassageEnvironment(BladeParameterRange::readDefault(), edgeRadii, scaling, trainingMeshes) {}
PassageEnvironment::PassageEnvironment()
    : PassageEnvironment(EdgeRadiusDraw::halfLogUniform,
                         policyStateScaling(BladeParameterRange::readDefault())) {}

int PassageEnvironment::stateSize() const { return policyStateSize; }
int PassageEnvironment::actionSize() const { return policyActionSize; }

std::vector<double> PassageEnvironment::defaultAction() const {
  const PolicyAction a = policyAction(MeshingParameters::defaults(1.0), 1.0);
  return {a.begin(), a.end()};
}

PassageCase PassageEnvironment::passage(std::uint64_t seed, std::uint64_t episode) const {
  std::mt19937_64 rng = episodeRandom(seed, episode, 0);
  BladeSampler sampler(range_, rng(), edgeRadii_);
  const BladeParameters blade = sampler.next();
  const PassageCondition condition = sampleCondition(blade.chord, rng);
  return PassageCase{BladeShape(blade), condition, MeshingParameters::defaults(blade.chord)};
}

EpisodeTask PassageEnvironment::draw(std::uint64_t seed, std::uint64_t episode, EpisodePurpose purpose) const {
  auto input = std::make_shared<const PassageCase>(passage(seed, episode));
  const PolicyState state = policyState(input->blade.parameters(), input->condition, scaling_);
  EpisodeTask task;
  task.state.assign(state.begin(), state.end());
  const bool asAsked = purpose == EpisodePurpose::training && trainingMeshes_ == TrainingMeshes::asAsked;
  const HohMeshOptions mesher = asAsked ? HohMeshOptions{}.withoutParameterMoves() : HohMeshOptions{};
  task.reward = [input, mesher](const std::vector<double>& action) {
    PolicyAction a{};
    for (int k = 0; k < policyActionSize; ++k) a[k] = action.at(k);
    return meshQualityOf(*input, meshingParametersOf(a, input->blade.parameters().chord), mesher);
  };
  return task;
}

}  // namespace passageMesh
