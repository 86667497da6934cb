#pragma once
// The single-step actor-critic training loop (method.md section 6; docs/policy.md).
//
// Episodes run in synchronous batches of batchEpisodes: the batch's tasks are drawn from
// their own random streams (PolicyEnvironment), the actor as it stands gives their actions
// plus Gaussian noise from each episode's own noise stream, the rewards are computed by the
// RolloutEvaluator (threads or MPI ranks), and then, episode by episode in order, the
// episode enters the replay buffer and the learner takes its updates (critic every
// episode, actor every actorUpdateEvery); with learnerSchedule duringNextRollouts the
// learner takes them while the next batch's meshes are built, that batch's actions coming
// from the actor before those updates. With options.searchEvery > 0 a search of one
// passage's actions follows every searchEvery episodes (search-guided exploration,
// PolicyTrainOptions.hpp). Nothing depends on the number of threads or ranks, and a
// checkpoint taken between batches resumes to the same weights bit for bit. Under
// duringNextRollouts a run also builds the batch past its end while it learns its last one
// (kept in the checkpoint), so that a -resume to more episodes gives the weights of one
// straight run of that length (when <episodes> is a multiple of batchEpisodes).
#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "passageMesh/policy/ActorCritic.hpp"
#include "passageMesh/policy/PolicyEnvironment.hpp"
#include "passageMesh/policy/PolicyTrainOptions.hpp"
#include "passageMesh/policy/ReplayBuffer.hpp"
#include "passageMesh/policy/RolloutEvaluator.hpp"

namespace passageMesh {

class Policy;

// A row of the learning curve, every logEvery episodes.
struct LearningRecord {
  long episode = 0;
  double meanReward = 0;   // of the last logEvery episodes (with exploration noise)
  double validFraction = 0;  // of those, the share with reward > -1
  double criticLoss = 0;   // mean over the updates since the last row
  double sigma = 0;        // exploration noise at this episode
  double seconds = 0;      // training time so far (all runs of a resumed training)
};

// A validation: the noise-free policy on the fixed validation passages.
struct ValidationRecord {
  long episode = 0;
  double meanReward = 0;
  double medianReward = 0;
  int valid = 0;  // passages with a valid mesh
  int passages = 0;
};

class PolicyTrainer {
 public:
  PolicyTrainer(const PolicyTrainOptions& options, const PolicyEnvironment& environment,
                RolloutEvaluator& rollouts);

  // Continues from a checkpoint written by saveCheckpoint with the same layout and seed;
  // an unreadable or mismatched checkpoint is an InputError naming the file. With
  // sameSettings false the checkpoint may come from a run with another seed and other
  // settings (the same networks): its weights, optimisers, buffer, curves and episode
  // count carry on under this trainer's settings (policyTrain -startFrom); a batch built but
  // not yet learnt (a checkpoint of learnerSchedule duringNextRollouts) is learnt first
  // under either schedule. A checkpoint whose built episodes pass options.episodes is
  // refused (the run would end past them), unless it has learnt them all (nothing to run).
  // The batch a finished duringNextRollouts run built past its end is continued with
  // sameSettings and dropped without (the new run builds its first batch itself).
  void resume(const std::filesystem::path& checkpoint, bool sameSettings = true);
  // Starts the actor as a trained policy's (policyTrain -actorFrom): a single policy whose
  // state was scaled as `scaling` (this run's), with this run's hidden layers and as many or
  // fewer actions; actions it lacks (the splits of a policy of the method's eight) start at
  // 0. The critic, buffer and episode count stay a new run's. A mismatch or an ensemble is
  // an InputError naming the policy file.
  void startActorFrom(const Policy& policy, const PolicyStateScaling& scaling);

  struct Events {
    std::function<void(const PolicyTrainer&)> afterBatch;        // progress lines
    std::function<void(const PolicyTrainer&)> newBestValidation;  // save the policy
    std::function<void(const PolicyTrainer&)> learnerRestored;    // a collapse was undone (restores())
    std::function<void(const PolicyTrainer&)> checkpointDue;      // save a checkpoint
  };
  // Trains until options.episodes or until *stop is set (checked between batches).
  // Returns true when all episodes are done.
  bool run(const std::atomic<bool>* stop, const Events& events);

  // Atomic (a temporary file renamed into place).
  void saveCheckpoint(const std::filesystem::path& file) const;

  const PolicyTrainOptions& options() const { return options_; }
  long episode() const { return episode_; }
  const ActorCritic& learner() const { return learner_; }
  const ReplayBuffer& buffer() const { return buffer_; }
  // The rewards of the newest min(count, 1000 or logEvery) training episodes, newest first
  // (the searches' meshes, which also enter the buffer, are not episodes).
  std::vector<double> recentRewards(long count) const;
  // The searches' best actions (rewards: their Q).
  const ReplayBuffer& demonstrations() const { return demonstrations_; }
  // Searches so far, and their mean gain (best Q minus the Q of the actor's action) over
  // those where the actor's mesh was valid.
  struct SearchSummary {
    long searches = 0;
    double meanGain = 0;
  };
  SearchSummary searchSummary() const {
    return {searches_, gainSearches_ ? searchGainSum_ / static_cast<double>(gainSearches_) : 0.0};
  }
  const std::vector<LearningRecord>& learningCurve() const { return learning_; }
  const std::vector<ValidationRecord>& validationCurve() const { return validation_; }
  // The validation of a fixed action for every passage (the environment's default action:
  // the baseline); nothing of the trainer's state changes. An action of another size than
  // the environment's is std::invalid_argument.
  ValidationRecord validateAction(const std::vector<double>& action) const;
  // The validation of the current weights (what policyMesh would give on each passage),
  // recorded at the current episode; nothing of the trainer's state changes. The curve
  // holds one every options.validationEvery episodes; this gives it for weights in between
  // (those of a run stopped with Ctrl-C).
  ValidationRecord validateCurrentPolicy() const;
  // Best validation mean reward so far (-infinity before the first).
  double bestValidation() const { return bestValidation_; }
  // The episodes at which a validation below options.restoreBelowValidShare of the best's
  // valid meshes took the learner back to its state at the best validation.
  const std::vector<long>& restores() const { return restores_; }
  double secondsTrained() const;  // this run's time plus that of the runs before a resume

 private:
  void runBatch();
  void learnPending();
  // Episodes whose meshes are built: those learnt and the pending batch.
  long builtEpisodes() const { return episode_ + pending_.actions.rows(); }
  void learnFrom(const std::vector<double>& state, const std::vector<double>& action, double reward);
  void validate();
  void search(std::uint64_t index);
  Imitation imitationBatch();
  // Throws: the actor's actions hold NaN (the learning rates too large for the rewards).
  [[noreturn]] void throwDiverged() const;

  PolicyTrainOptions options_;
  const PolicyEnvironment& environment_;
  RolloutEvaluator& rollouts_;
  ActorCritic learner_;
  ReplayBuffer buffer_;
  ReplayBuffer demonstrations_;
  std::vector<double> recentRewards_;  // newest last, at most recentCapacity()
  long searches_ = 0, gainSearches_ = 0;
  double searchGainSum_ = 0;
  std::mt19937_64 minibatchRandom_;
  long episode_ = 0;  // episodes the learner has taken
  // The batch whose meshes are built but whose episodes the learner has not taken yet
  // (learnerSchedule duringNextRollouts; empty between batches otherwise).
  struct PendingBatch {
    PolicyBatch states, actions;
    Eigen::VectorXd rewards;
  } pending_;
  std::vector<LearningRecord> learning_;
  std::vector<ValidationRecord> validation_;
  double bestValidation_;
  int bestValid_ = 0;              // valid meshes of the best validation
  std::string bestLearnerState_;   // the learner then (empty: restores off, or no best yet)
  std::vector<long> restores_;     // episodes at which a collapse took the learner back
  double lossSum_ = 0;
  long lossCount_ = 0;
  double secondsBefore_ = 0;  // from the checkpoint
  std::chrono::steady_clock::time_point start_;
  std::vector<EpisodeTask> validationTasks_;
};

}  // namespace passageMesh
