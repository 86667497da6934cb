#pragma once
// The single-step actor-critic learner (method.md section 6): the critic Q(s, a) fitted to
// the rewards by mean squared error (or split into validity and quality, CriticModel in
// NetworkLayout.hpp), the actor pi(s) moved up the critic's gradient
// (deterministic policy gradient), each with its own Adam optimiser. LibTorch, CPU, float32,
// one thread; the LibTorch types stay inside the .cpp (pointer to implementation).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "passageMesh/policy/NetworkLayout.hpp"
#include "passageMesh/policy/ReplayBuffer.hpp"

namespace torch::serialize {
class OutputArchive;
class InputArchive;
}  // namespace torch::serialize

namespace passageMesh {

struct LearningRates {
  double actor = 1e-4;   // the paper's Adam learning rate for both
  double critic = 1e-4;
};

// Demonstrated actions the actor is pulled towards (search-guided exploration,
// PolicyTrainOptions::imitationWeight): rows of states and the actions to imitate there.
struct Imitation {
  PolicyBatch states, actions;  // no rows: no pull
  double weight = 0;
};

class ActorCritic {
 public:
  // Weights initialised by LibTorch's default rule from `seed`. A non-empty `startAction`
  // makes the actor start near that action for every state (FullyConnectedImpl::startAt).
  ActorCritic(const NetworkLayout& layout, const LearningRates& rates, std::uint64_t seed,
              const std::vector<double>& startAction = {});
  ~ActorCritic();
  ActorCritic(ActorCritic&&) noexcept;
  ActorCritic& operator=(ActorCritic&&) noexcept;

  const NetworkLayout& layout() const;
  // The actor's weights from a saved actor of `fileLayout` (the same state size and hidden
  // layers, as many or fewer actions; FullyConnectedImpl::startFrom): actions it lacks start
  // at 0. The critic and the optimisers' states are left as they are. Throws
  // std::invalid_argument naming what differs. The file is read again here: pass one that
  // Policy::load has already read and checked (PolicyTrainer::startActorFrom does).
  void startActorFrom(const std::filesystem::path& actorFile, const NetworkLayout& fileLayout);

  // From now on updateActor moves only these outputs' rows of the actor's output layer; its
  // hidden layers and the other outputs keep their weights bit for bit (empty: every weight
  // learns, the paper's). For an actor started from a trained policy that lacked these
  // actions (startActorFrom): the new actions learn on the trained features while the
  // trained ones stay as they were (docs/policy.md "Ten actions"). Throws
  // std::invalid_argument for an output outside the actor's.
  void trainActorOutputsOnly(const std::vector<int>& outputs);
  // Holds these outputs where they are for every state: their rows of the actor's output
  // layer get zero weights now (each output is then its bias through the tanh: the start
  // action's value after a start at it) and never move, while every other weight learns
  // (empty: none held). For a policy trained without some actions, e.g. the method's eight
  // with the interface splits held at 0 (PolicyTrainOptions::heldActions). Throws
  // std::invalid_argument for an output outside the actor's.
  void holdActorOutputs(const std::vector<int>& outputs);

  // Polyak averaging of the actor (PolicyTrainOptions::actorAverageDecay): the averaged
  // actor starts as a copy of the actor now and, after each actor step, moves (1 - decay) of
  // the way to it; held outputs stay held in it, and startActorFrom starts it again at the
  // new actor. decay in (0, 1). The learning actor, and so the training, is the same as
  // without it.
  void averageActor(double decay);
  bool averagesActor() const;

  // pi(s) for each row of `states`: the learning actor, which the training explores with.
  PolicyBatch act(const PolicyBatch& states) const;
  // The actor the learner delivers for each row: the averaged one while averaging (see
  // averageActor), else the learning actor. Validations score it and saveActor writes it.
  PolicyBatch actDelivered(const PolicyBatch& states) const;
  // Q(s, a), the critic's expected reward, for each row.
  Eigen::VectorXd value(const PolicyBatch& states, const PolicyBatch& actions) const;

  // One Adam step of the critic on mean((Q(s, a) - r)^2) (with a validity network: one step
  // of each network on its own loss); returns mean((Q(s, a) - r)^2) before the step.
  double updateCritic(const PolicyBatch& states, const PolicyBatch& actions,
                      const Eigen::VectorXd& rewards);
  // One Adam step of the actor on -mean(Q(s, pi(s))) + boundPenalty * mean over states and
  // actions of max(0, |u| - atanh(0.95))^2, u the actor's output before tanh; returns mean
  // Q(s, pi(s)) before the step.
  // With a validity network (hasValidity) and validityBarrier > 0 the actor climbs
  // q(s, a) + validityBarrier * log p(s, a) instead of the expected reward (and returns
  // mean q).
  // A non-empty `imitation` adds weight * mean over its rows of |u(s) - atanh(a')|^2, u the
  // actor's output before tanh and a' the demonstrated action clipped to +-0.95.
  double updateActor(const PolicyBatch& states, double boundPenalty = 0, double validityBarrier = 0,
                     const Imitation& imitation = {});

  // Both networks and both optimisers' states (and the averaged actor while averaging),
  // for checkpoints. Loading a state without an averaged actor while averaging starts the
  // average at the loaded actor.
  void save(torch::serialize::OutputArchive& archive) const;
  void load(torch::serialize::InputArchive& archive);
  // The same as bytes in memory (the trainer keeps the best validation's learner so).
  std::string stateBytes() const;
  // "the critic's layers.0.weight holds NaN or infinity" where a network's weight does (a
  // diverged learner), else "" (nonFiniteWeightProblem, PolicyNetworks.hpp). load()
  // refuses such a state.
  std::string nonFiniteWeightProblem() const;
  void loadStateBytes(const std::string& bytes);
  // The delivered actor (actDelivered) alone, with LibTorch's own serialisation (Python:
  // torch.jit.load), written atomically (PolicyFile.hpp writes it with its description).
  void saveActor(const std::filesystem::path& file) const;

 private:
  struct Networks;
  std::unique_ptr<Networks> networks_;
};

}  // namespace passageMesh
