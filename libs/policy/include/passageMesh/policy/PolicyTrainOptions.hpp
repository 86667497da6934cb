#pragma once
// Everything policyTrain can be told, read from system/policyTrainDict.xml
// (docs/case-format.md). The defaults are the paper's settings (method.md section 6)
// where it gives them.
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "passageMesh/blade/BladeSampler.hpp"
#include "passageMesh/policy/ActorCritic.hpp"
#include "passageMesh/policy/NetworkLayout.hpp"
#include "passageMesh/policy/PolicyEnvironment.hpp"

namespace passageMesh {

// The actor's first weights: LibTorch's default rule (the paper's), or that rule and then
// moved so that the actor starts at the environment's default action, or at the action of
// a meshDict file's parameters (PolicyTrainOptions::actorStartMeshDict).
enum class ActorStart { random, defaults, meshDict };

// When the learner takes a batch's episodes: after its rollouts, before the next batch's
// actions (afterRollouts, the paper's order), or while the next batch's meshes are built
// (duringNextRollouts: the learner's thread works beside the rollouts instead of after
// them, and each batch's actions come from the actor before the previous batch's updates).
enum class LearnerSchedule { afterRollouts, duringNextRollouts };

struct PolicyTrainOptions {
  long episodes = 100000;         // episodes in the whole run (a resumed run continues to it)
  int batchEpisodes = 32;         // rollouts per batch: one actor snapshot, built in parallel
  int minibatch = 100;            // replay minibatch per update (paper: 100)
  LearningRates learningRates;    // Adam (paper: 1e-4 for both)
  std::vector<int> hidden{512, 256, 256, 128};  // hidden layers of both networks (paper)
  double leakySlope = 0.01;
  int criticUpdatesPerEpisode = 1;  // paper: 1
  int actorUpdateEvery = 2;         // episodes per actor update (paper: 2)
  // No actor updates before this episode (0: from the first, the paper's): the critic
  // learns first, so that an actor started from a trained policy (policyTrain -actorFrom)
  // is not pushed along an untrained critic's gradient (docs/policy.md "Ten actions").
  long actorUpdatesFrom = 0;
  // The actions whose output rows the actor's steps move, as indices into the action (the
  // dictionary names them: <actorTrainsOnly>splitIn splitOut</actorTrainsOnly>); the
  // hidden layers and the other actions keep their start weights. Empty: every weight
  // learns (the paper's). For a start from a trained policy without these actions
  // (policyTrain -actorFrom; ActorCritic::trainActorOutputsOnly, docs/policy.md).
  std::vector<int> actorTrainedActions;
  // The actions the actor holds at its start for every state (indices; the dictionary names
  // them: <heldActions>splitIn splitOut</heldActions>): their output rows get zero weights
  // and never learn, and they get no exploration noise, while every other weight learns.
  // With actorStart defaults the splits are then 0, the method's outer loop: a policy of the
  // method's eight actions (those before 2026-12-06) trained with today's ten-action layout.
  // Empty: none (the paper's). Not with actorTrainedActions.
  std::vector<int> heldActions;
  // Weight of the actor's penalty on pre-tanh outputs beyond atanh(0.95), the action at
  // 95 % of its half-range (0: none, the paper's): keeps tanh off its flat ends, where the
  // actor's gradient vanishes and a saturated action cannot come back (docs/policy.md).
  double actionBoundPenalty = 0;
  // A validation that meshes fewer than this share of the passages the best validation so
  // far meshed takes the learner (networks and optimisers) back to its state at that best,
  // and training goes on from there with the buffer as it is (0: never, the paper's). A
  // collapsed actor, every action on a bound where tanh is flat, does not come back by
  // itself (docs/policy.md "Collapses"); a run without such a validation is unchanged.
  double restoreBelowValidShare = 0.5;
  // Polyak averaging of the actor's weights (0: none, the paper's): after each actor step
  // the averaged actor moves (1 - decay) of the way to the learning one, and it is what
  // the validations score and the policy files hold, while the learning actor explores and
  // learns as without it (Polyak and Juditsky, SIAM J. Control Optim. 30, 1992;
  // docs/policy.md "The averaged actor"). 0.999: a memory of about 1000 actor steps.
  double actorAverageDecay = 0;
  // Exploration noise on the actions (scaled units): sigma = noiseStartSigma for the first
  // noiseStartEpisodes, then noiseAmplitude (cos(2 pi episode / noisePeriod) + 1)
  // (paper: 1, 1000, 0.25, 1000).
  double noiseStartSigma = 1.0;
  long noiseStartEpisodes = 1000;
  double noiseAmplitude = 0.25;
  long noisePeriod = 1000;
  // This share of the episodes (drawn per episode from its noise stream) explores with
  // sigma = wideNoiseSigma instead of the schedule's: far from the actor's action, where
  // the critic has seen nothing, while the other episodes keep the data near it (0: none,
  // the paper's; docs/policy.md).
  double wideNoiseShare = 0;
  double wideNoiseSigma = 0.5;
  // The actions a wide episode widens (indices; the dictionary names them), the others
  // keeping the schedule's sigma; empty: all of them.
  std::vector<int> wideNoiseActions;
  long bufferCapacity = 1000000;  // replay buffer episodes (the newest kept)
  long validationEvery = 5000;    // episodes between validations (noise-free policy)
  int validationPassages = 50;    // fixed sampler passages of the validation set
  std::uint64_t validationSeed = 20261202;  // their stream (not the training stream)
  long checkpointEvery = 5000;    // episodes between checkpoints
  long logEvery = 1000;           // episodes between learning-curve rows
  // The actor's first weights (for the passages: etc/meshDictDefaults.xml's action;
  // docs/policy.md measures them). With meshDict: the file as the dictionary names it
  // (relative to the case directory) and its parameters for a chord of 1 m (lengths in
  // chords), read by readPolicyTrainDict.
  ActorStart actorStart = ActorStart::defaults;
  std::filesystem::path actorStartMeshDict;
  MeshingParameters actorStartParameters;
  // The training passages' edge radii: halfLogUniform (each radius log-uniform in its
  // range with probability 1/2, logarithmic in the state: sharp edges are common and told
  // apart) or uniform (uniform draws, linear in the state: the policies trained before
  // the twelfth session, 2026-12-04). docs/policy.md measures both.
  EdgeRadiusDraw edgeRadii = EdgeRadiusDraw::halfLogUniform;
  // How the training episodes' (and searches') meshes are built: asPolicyMesh (the
  // mesher's parameter moves where a mesh as asked is invalid, as policyMesh) or asAsked
  // (no moves: -1 for such an episode, a fraction of the time). Validation meshes as
  // policyMesh either way (PolicyEnvironment.hpp; docs/policy.md "Training meshes").
  TrainingMeshes trainingMeshes = TrainingMeshes::asPolicyMesh;
  // When the learner takes a batch (LearnerSchedule above; docs/policy.md "Training loop").
  LearnerSchedule learnerSchedule = LearnerSchedule::afterRollouts;
  // What the critic predicts: reward (the paper's), validityAndQuality or
  // validityAndBoundedQuality (NetworkLayout.hpp; docs/policy.md measures them).
  CriticModel criticModel = CriticModel::reward;
  // With a validity network: 0 makes the actor climb the expected reward; lambda > 0 makes
  // it climb q + lambda log p (ActorCritic::updateActor).
  double validityBarrier = 0;
  // Search-guided exploration (docs/policy.md): every searchEvery episodes (0: never, the
  // paper's) a CMA-ES search of searchBudget meshes, started at the actor's action, on a
  // passage of its own stream; every mesh it builds enters the replay buffer (the critic
  // learns the regions the noise does not reach), and its best action becomes a
  // demonstration. imitationWeight > 0 adds to the actor's loss the squared distance
  // (ActorCritic::updateActor) to the demonstrations whose Q is above the critic's value
  // of the actor's action there.
  long searchEvery = 0;
  int searchBudget = 64;
  double imitationWeight = 0;
  std::uint64_t seed = 1;         // weights, episodes, noise and minibatches
  int threads = 0;                // rollout threads per process (0 = all cores)

  // The exploration sigma at a (0-based) episode.
  double noiseSigma(long episode) const;
  NetworkLayout layout(int stateSize, int actionSize) const;
  // The sampler passages this training draws, scaled as its edgeRadii says.
  PassageEnvironment passageEnvironment() const;
  // The action the actor starts at (empty for random).
  std::vector<double> actorStartAction(const PolicyEnvironment& environment) const;
};

// The words of the dictionary (and of the benches' command lines) for the enumerated
// settings, one table each: an unknown word is an InputError listing the known ones, and
// nameOf gives a value's word.
ActorStart actorStartNamed(const std::string& word);
EdgeRadiusDraw edgeRadiusDrawNamed(const std::string& word);
CriticModel criticModelNamed(const std::string& word);
TrainingMeshes trainingMeshesNamed(const std::string& word);
LearnerSchedule learnerScheduleNamed(const std::string& word);
std::string nameOf(ActorStart value);
std::string nameOf(EdgeRadiusDraw value);
std::string nameOf(CriticModel value);
std::string nameOf(TrainingMeshes value);
std::string nameOf(LearnerSchedule value);

// A missing file gives the defaults; a missing key keeps its default; an unknown key, a
// malformed or out-of-range value is an InputError naming the file and the line.
PolicyTrainOptions readPolicyTrainDict(const std::filesystem::path& file);
// The dictionary's text with every key (17 significant digits).
std::string policyTrainDictXml(const PolicyTrainOptions& options);
// "key value" lines of the settings that decide the weights (all but episodes, threads,
// checkpointEvery and logEvery), for checking that a resumed run continues the same one.
std::vector<std::pair<std::string, std::string>> trajectorySettings(const PolicyTrainOptions& options);

}  // namespace passageMesh
