#include "passageMesh/policy/ToyEnvironment.hpp"

#include <cmath>

namespace passageMesh {

ToyEnvironment::ToyEnvironment(int stateSize, int actionSize, std::uint64_t seed, double cliff)
    : stateSize_(stateSize), actionSize_(actionSize), cliff_(cliff) {
  std::mt19937_64 rng(seed);
  std::vector<double> w(static_cast<std::size_t>(stateSize * actionSize));
  for (int i = 0; i < actionSize; ++i) {
    double norm = 0;
    for (int j = 0; j < stateSize; ++j) {
      double& v = w[static_cast<std::size_t>(i * stateSize + j)];
      v = standardNormal(rng);
      norm += v * v;
    }
    for (int j = 0; j < stateSize; ++j) w[static_cast<std::size_t>(i * stateSize + j)] /= std::sqrt(norm);
  }
  weights_ = std::make_shared<const std::vector<double>>(std::move(w));
}

std::vector<double> ToyEnvironment::optimum(const std::vector<double>& state) const {
  std::vector<double> x(static_cast<std::size_t>(actionSize_));
  for (int i = 0; i < actionSize_; ++i) {
    double sum = 0;
    for (int j = 0; j < stateSize_; ++j)
      sum += (*weights_)[static_cast<std::size_t>(i * stateSize_ + j)] * state[static_cast<std::size_t>(j)];
    x[static_cast<std::size_t>(i)] = 0.8 * std::tanh(sum);
  }
  return x;
}

EpisodeTask ToyEnvironment::draw(std::uint64_t seed, std::uint64_t episode, EpisodePurpose) const {
  std::mt19937_64 rng = episodeRandom(seed, episode, 0);
  EpisodeTask task;
  task.state.resize(static_cast<std::size_t>(stateSize_));
  for (double& s : task.state) s = 2.0 * uniform01(rng) - 1.0;
  auto target = std::make_shared<const std::vector<double>>(optimum(task.state));
  task.reward = [target, cliff = cliff_](const std::vector<double>& action) {
    if (action.at(0) - target->at(0) > cliff) return -1.0;
    double sum = 0;
    for (std::size_t k = 0; k < target->size(); ++k) {
      const double d = action.at(k) - (*target)[k];
      sum += d * d;
    }
    return 1.0 - std::sqrt(sum / static_cast<double>(target->size()));
  };
  return task;
}

double ToyEnvironment::actionError(const ActorCritic& learner, std::uint64_t seed, int count) const {
  std::vector<EpisodeTask> tasks;
  std::vector<std::vector<double>> optima;
  for (int i = 0; i < count; ++i) {
    tasks.push_back(draw(seed, static_cast<std::uint64_t>(i), EpisodePurpose::validation));
    optima.push_back(optimum(tasks.back().state));
  }
  const PolicyBatch actions = learner.act(statesOf(tasks, stateSize_));
  double sum = 0;
  for (int i = 0; i < count; ++i)
    for (int k = 0; k < actionSize_; ++k) {
      const double d = actions(i, k) - optima[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
      sum += d * d;
    }
  return std::sqrt(sum / (static_cast<double>(count) * actionSize_));
}

}  // namespace passageMesh
