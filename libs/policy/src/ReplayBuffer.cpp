#include "passageMesh/policy/ReplayBuffer.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "passageMesh/blade/BladeSampler.hpp"

namespace passageMesh {

ReplayBuffer::ReplayBuffer(int stateSize, int actionSize, long capacity)
    : stateSize_(stateSize), actionSize_(actionSize), capacity_(capacity) {
  if (stateSize < 1 || actionSize < 1 || capacity < 1)
    throw std::invalid_argument("ReplayBuffer: sizes and capacity must be positive");
}

void ReplayBuffer::add(const std::vector<double>& state, const std::vector<double>& action,
                       double reward) {
  if (static_cast<int>(state.size()) != stateSize_ || static_cast<int>(action.size()) != actionSize_)
    throw std::invalid_argument("ReplayBuffer::add: state or action of the wrong size");
  if (next_ >= states_.rows() && states_.rows() < capacity_) {
    // Grow geometrically up to the capacity, so a short run does not hold a full buffer.
    const long rows = std::min(capacity_, std::max<long>(1024, 2 * states_.rows()));
    states_.conservativeResize(rows, stateSize_);
    actions_.conservativeResize(rows, actionSize_);
    rewards_.conservativeResize(rows);
  }
  states_.row(next_) = Eigen::Map<const Eigen::RowVectorXd>(state.data(), stateSize_);
  actions_.row(next_) = Eigen::Map<const Eigen::RowVectorXd>(action.data(), actionSize_);
  rewards_[next_] = reward;
  next_ = (next_ + 1) % capacity_;
  size_ = std::min(size_ + 1, capacity_);
}

long ReplayBuffer::slot(long age) const { return ((next_ - 1 - age) % capacity_ + capacity_) % capacity_; }

void ReplayBuffer::sample(int count, std::mt19937_64& rng, PolicyBatch& states, PolicyBatch& actions,
                          Eigen::VectorXd& rewards) const {
  if (size_ == 0) throw std::logic_error("ReplayBuffer::sample: the buffer is empty");
  states.resize(count, stateSize_);
  actions.resize(count, actionSize_);
  rewards.resize(count);
  for (int i = 0; i < count; ++i) {
    const long age = std::min(size_ - 1, static_cast<long>(uniform01(rng) * static_cast<double>(size_)));
    const long row = slot(age);
    states.row(i) = states_.row(row);
    actions.row(i) = actions_.row(row);
    rewards[i] = rewards_[row];
  }
}

std::vector<double> ReplayBuffer::recentRewards(long count) const {
  std::vector<double> r(static_cast<std::size_t>(std::max(0L, std::min(count, size_))));
  for (std::size_t age = 0; age < r.size(); ++age) r[age] = rewards_[slot(static_cast<long>(age))];
  return r;
}

void ReplayBuffer::exportEpisodes(PolicyBatch& states, PolicyBatch& actions,
                                  Eigen::VectorXd& rewards) const {
  states.resize(size_, stateSize_);
  actions.resize(size_, actionSize_);
  rewards.resize(size_);
  for (long i = 0; i < size_; ++i) {
    const long row = slot(size_ - 1 - i);
    states.row(i) = states_.row(row);
    actions.row(i) = actions_.row(row);
    rewards[i] = rewards_[row];
  }
}

void ReplayBuffer::importEpisodes(const PolicyBatch& states, const PolicyBatch& actions,
                                  const Eigen::VectorXd& rewards) {
  const long n = states.rows();
  if (states.cols() != stateSize_ || actions.cols() != actionSize_ || actions.rows() != n ||
      rewards.size() != n || n > capacity_)
    throw std::invalid_argument("ReplayBuffer::importEpisodes: " + std::to_string(n) +
                                " episodes do not fit this buffer's layout");
  states_ = states;
  actions_ = actions;
  rewards_ = rewards;
  size_ = n;
  next_ = n % capacity_;
}

}  // namespace passageMesh
