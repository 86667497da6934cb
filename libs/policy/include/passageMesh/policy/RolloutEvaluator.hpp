#pragma once
// Where the rewards of a batch of episodes are computed: threads of this process
// (ThreadRollouts) or MPI ranks (MpiRollouts.hpp). Either way episode i's reward depends on
// its task and action only, so training gives the same weights wherever rollouts run.
#include <cstdint>
#include <functional>
#include <vector>

#include "passageMesh/policy/PolicyEnvironment.hpp"
#include "passageMesh/policy/ReplayBuffer.hpp"

namespace passageMesh {

// Which episodes a batch's rows are: row i is episode first + i * step of stream `seed` (a
// remote rank draws them again from that). step 0: every row is the same episode, as in a
// search over one passage's actions. `purpose`: what the rows were drawn for.
struct EpisodeRange {
  std::uint64_t seed = 0, first = 0, step = 1;
  EpisodePurpose purpose = EpisodePurpose::training;
  std::uint64_t episode(std::size_t row) const { return first + row * step; }
};

class RolloutEvaluator {
 public:
  virtual ~RolloutEvaluator() = default;
  // The reward of each task under the action in the same row; `tasks` are the episodes
  // `range` names.
  virtual std::vector<double> rewards(const std::vector<EpisodeTask>& tasks, const PolicyBatch& actions,
                                      const EpisodeRange& range) = 0;
  // The same rewards, with `meanwhile` run on the calling thread while they are computed
  // (the learner beside the rollouts: PolicyTrainOptions' learnerSchedule); an exception of
  // either comes out after both have ended (meanwhile's first). This default runs
  // `meanwhile` after the rewards, and not at all where they throw.
  virtual std::vector<double> rewardsWhile(const std::vector<EpisodeTask>& tasks, const PolicyBatch& actions,
                                           const EpisodeRange& range, const std::function<void()>& meanwhile);
  // Processes and threads taking part, for the progress line.
  virtual std::string description() const = 0;
};

class ThreadRollouts final : public RolloutEvaluator {
 public:
  explicit ThreadRollouts(int threads);  // 0 = all cores
  std::vector<double> rewards(const std::vector<EpisodeTask>& tasks, const PolicyBatch& actions,
                              const EpisodeRange& range) override;
  std::vector<double> rewardsWhile(const std::vector<EpisodeTask>& tasks, const PolicyBatch& actions,
                                   const EpisodeRange& range, const std::function<void()>& meanwhile) override;
  std::string description() const override;

 private:
  int threads_;
};

// Rewards of tasks[i] for indices i where i % stride == offset (the others left 0), on
// `threads` threads: the shared loop of both evaluators.
void rewardsOfSlice(const std::vector<EpisodeTask>& tasks, const PolicyBatch& actions, int offset,
                    int stride, int threads, std::vector<double>& rewards);

}  // namespace passageMesh
