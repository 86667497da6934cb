#pragma once
// The replay buffer of single-step episodes (state, action, reward): a ring that keeps the
// newest `capacity` episodes; minibatches are drawn uniformly with replacement.
#include <Eigen/Core>
#include <random>
#include <vector>

namespace passageMesh {

// Rows are episodes.
using PolicyBatch = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

class ReplayBuffer {
 public:
  ReplayBuffer(int stateSize, int actionSize, long capacity);

  void add(const std::vector<double>& state, const std::vector<double>& action, double reward);
  long size() const { return size_; }
  long capacity() const { return capacity_; }
  int stateSize() const { return stateSize_; }
  int actionSize() const { return actionSize_; }

  // `count` episodes drawn uniformly with replacement (the buffer must not be empty).
  void sample(int count, std::mt19937_64& rng, PolicyBatch& states, PolicyBatch& actions,
              Eigen::VectorXd& rewards) const;
  // The rewards of the newest min(count, size) episodes, newest first.
  std::vector<double> recentRewards(long count) const;

  // The stored episodes oldest first, for checkpoints, and a buffer rebuilt from them.
  void exportEpisodes(PolicyBatch& states, PolicyBatch& actions, Eigen::VectorXd& rewards) const;
  void importEpisodes(const PolicyBatch& states, const PolicyBatch& actions,
                      const Eigen::VectorXd& rewards);

 private:
  long slot(long age) const;  // storage row of the episode `age` steps before the newest

  int stateSize_, actionSize_;
  long capacity_;
  long size_ = 0;
  long next_ = 0;  // storage row the next episode goes to
  PolicyBatch states_, actions_;
  Eigen::VectorXd rewards_;
};

}  // namespace passageMesh
