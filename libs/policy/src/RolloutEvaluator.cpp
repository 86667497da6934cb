#include "passageMesh/policy/RolloutEvaluator.hpp"

#include <string>

#include "passageMesh/core/ParallelFor.hpp"

namespace passageMesh {

void rewardsOfSlice(const std::vector<EpisodeTask>& tasks, const PolicyBatch& actions, int offset,
                    int stride, int threads, std::vector<double>& rewards) {
  const int count = static_cast<int>(tasks.size());
  rewards.assign(tasks.size(), 0.0);
  const int mine = count > offset ? (count - offset + stride - 1) / stride : 0;
  parallelFor(mine, threads, [&](int k) {
    const int i = offset + k * stride;
    const auto row = actions.row(i);
    rewards[static_cast<std::size_t>(i)] =
        tasks[static_cast<std::size_t>(i)].reward(std::vector<double>(row.data(), row.data() + row.size()));
  });
}

std::vector<double> RolloutEvaluator::rewardsWhile(const std::vector<EpisodeTask>& tasks,
                                                   const PolicyBatch& actions, const EpisodeRange& range,
                                                   const std::function<void()>& meanwhile) {
  std::vector<double> r = rewards(tasks, actions, range);
  meanwhile();
  return r;
}

ThreadRollouts::ThreadRollouts(int threads) : threads_(threads) {}

std::vector<double> ThreadRollouts::rewards(const std::vector<EpisodeTask>& tasks,
                                            const PolicyBatch& actions, const EpisodeRange&) {
  std::vector<double> r;
  rewardsOfSlice(tasks, actions, 0, 1, threads_, r);
  return r;
}

std::vector<double> ThreadRollouts::rewardsWhile(const std::vector<EpisodeTask>& tasks,
                                                 const PolicyBatch& actions, const EpisodeRange&,
                                                 const std::function<void()>& meanwhile) {
  std::vector<double> r;
  runBeside([&] { rewardsOfSlice(tasks, actions, 0, 1, threads_, r); }, meanwhile);
  return r;
}

std::string ThreadRollouts::description() const {
  return std::to_string(resolvedThreads(threads_)) + " rollout threads";
}

}  // namespace passageMesh
