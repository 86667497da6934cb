#pragma once
// What the single-step actor-critic learns from: episodes that each give a state and a
// reward for any action (method.md section 6). An episode is named by a stream seed and its
// index, and drawing it again gives the same task on every run, thread and MPI rank, which
// is what keeps training independent of where rollouts run.
#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "passageMesh/blade/BladeSampler.hpp"
#include "passageMesh/passage/PassageCase.hpp"
#include "passageMesh/policy/PolicyScaling.hpp"
#include "passageMesh/policy/ReplayBuffer.hpp"

namespace passageMesh {

// What an episode is drawn for: a training episode (or a search's) may be meshed otherwise
// than the product meshes (PassageEnvironment's TrainingMeshes); validation and
// evaluation always mesh as policyMesh does.
enum class EpisodePurpose { training, validation };

struct EpisodeTask {
  std::vector<double> state;  // in [-1, 1]
  // The reward of an action in [-1, 1]^actionSize; callable from any thread.
  std::function<double(const std::vector<double>& action)> reward;
};

class PolicyEnvironment {
 public:
  virtual ~PolicyEnvironment() = default;
  virtual int stateSize() const = 0;
  virtual int actionSize() const = 0;
  virtual EpisodeTask draw(std::uint64_t seed, std::uint64_t episode, EpisodePurpose purpose) const = 0;
  // A known reasonable action for every state, where there is one (the actor may start
  // there); empty otherwise.
  virtual std::vector<double> defaultAction() const { return {}; }
};

// The tasks' states as the rows of a batch (the actor's input).
PolicyBatch statesOf(const std::vector<EpisodeTask>& tasks, int stateSize);

// Mean, median and count of a set of rewards, and how many are above -1, the reward of an
// invalid mesh (every summary the trainer, its progress line and the benches print).
struct RewardSummary {
  double mean = 0, median = 0;  // 0 for no rewards
  int valid = 0, count = 0;
};
RewardSummary summarizeRewards(const std::vector<double>& rewards);

// The random stream `stream` of episode `episode` under `seed`: independent streams
// without a shared generator (seeded through std::seed_seq, deterministic everywhere).
std::mt19937_64 episodeRandom(std::uint64_t seed, std::uint64_t episode, std::uint32_t stream);
// A standard normal variate from uniform01 (Box-Muller), the same on every platform.
double standardNormal(std::mt19937_64& rng);

// How a training episode's mesh is built: `asPolicyMesh`, as policyMesh builds it (where
// the mesh as asked is invalid, buildHohMesh moves the parameters and scores the first
// valid mesh); `asAsked`, with the action's parameters only (HohMeshOptions' parameter
// moves off: such an episode scores -1, and costs one try instead of up to 24;
// docs/policy.md "Training meshes").
enum class TrainingMeshes { asPolicyMesh, asAsked };

// Blade passages from the sampler (PassageSampler.hpp: a valid blade from the BSP box, a
// condition from PassageConditionRange); the reward is the mesh quality Q of the HOH mesh
// built with the action's meshing parameters (-1 for an invalid mesh).
//
// edgeRadii says how the blade sampler draws the edge radii (halfLogUniform: this build's
// training; uniform: the draws of policies trained before 2026-12-04's twelfth session),
// `scaling` how the state is scaled (the policy's own, Policy::stateScaling()).
class PassageEnvironment final : public PolicyEnvironment {
 public:
  PassageEnvironment(BladeParameterRange range, EdgeRadiusDraw edgeRadii, PolicyStateScaling scaling,
                     TrainingMeshes trainingMeshes = TrainingMeshes::asPolicyMesh);
  // etc/bladeParameterRange.xml, half log-uniform edge radii, logarithmic radii in the state.
  PassageEnvironment();
  // etc/bladeParameterRange.xml with the given draw and scaling.
  PassageEnvironment(EdgeRadiusDraw edgeRadii, PolicyStateScaling scaling,
                     TrainingMeshes trainingMeshes = TrainingMeshes::asPolicyMesh);
  const PolicyStateScaling& stateScaling() const { return scaling_; }
  int stateSize() const override;
  int actionSize() const override;
  EpisodeTask draw(std::uint64_t seed, std::uint64_t episode, EpisodePurpose purpose) const override;
  // The blade and condition draw() gives that episode (meshing parameters: the defaults),
  // e.g. to write a validation passage as a case.
  PassageCase passage(std::uint64_t seed, std::uint64_t episode) const;
  // The action of etc/meshDictDefaults.xml (the same for every chord).
  std::vector<double> defaultAction() const override;

 private:
  BladeParameterRange range_;
  EdgeRadiusDraw edgeRadii_;
  PolicyStateScaling scaling_;
  TrainingMeshes trainingMeshes_;
};

}  // namespace passageMesh
