#include "passageMesh/policy/PolicyTrainer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/ZipChecksums.hpp"
#include "passageMesh/policy/ActionSearch.hpp"
#include "passageMesh/policy/Policy.hpp"
#include "passageMesh/quality/MeshQuality.hpp"
#include "TorchTensors.hpp"

namespace passageMesh {

namespace {

constexpr const char* checkpointFormat = "passageMesh policyTrain checkpoint 1";
constexpr std::uint32_t noiseStream = 1;
constexpr std::uint32_t minibatchStream = 2;
constexpr std::uint32_t searchStream = 3;

// The searches' passages come from a stream of their own: seed XOR a constant, so they are
// not the training episodes' passages.
constexpr std::uint64_t searchPassageSeed(std::uint64_t seed) { return seed ^ 0x5ea4c4ed5ea4c4edULL; }

// The training episodes' rewards kept for the learning curve and the progress line.
long recentCapacity(const PolicyTrainOptions& o) { return std::max(o.logEvery, 1000L); }

std::string layoutText(const NetworkLayout& l) {
  std::ostringstream s;
  s.precision(17);
  s << l.stateSize << " " << l.actionSize << " [" << l.hiddenText() << "] " << l.leakySlope;
  // Checkpoints from before the critic models name none: `reward` stays unnamed.
  if (l.critic != CriticModel::reward) s << " " << nameOf(l.critic);
  return s.str();
}

// The settings that decide the weights, one "key value" line each.
std::string settingsText(const PolicyTrainOptions& options) {
  std::string text;
  for (const auto& [key, value] : trajectorySettings(options)) text += key + " " + value + "\n";
  return text;
}

// "<key> was X, is Y" for the first setting that differs; empty when none does. A key the
// checkpoint lacks (added to the dictionary after it was written) counts as its default.
std::string firstDifference(const std::string& before, const PolicyTrainOptions& options) {
  std::map<std::string, std::string> recorded;
  std::istringstream lines(before);
  for (std::string line; std::getline(lines, line);)
    recorded[line.substr(0, line.find(' '))] = line.find(' ') == std::string::npos ? "" : line.substr(line.find(' ') + 1);
  const auto defaults = trajectorySettings(PolicyTrainOptions{});
  const auto now = trajectorySettings(options);
  for (std::size_t k = 0; k < now.size(); ++k) {
    const auto& [key, value] = now[k];
    const auto found = recorded.find(key);
    const std::string was = found != recorded.end() ? found->second : defaults[k].second;
    if (was != value) return "<" + key + "> was " + was + ", is " + value;
    if (found != recorded.end()) recorded.erase(found);
  }
  return recorded.empty() ? "" : "<" + recorded.begin()->first + "> is no longer a setting";
}

// The rows of the validation set (the batch the validation's rewards come from).
EpisodeRange validationRange(const PolicyTrainOptions& options) {
  return {options.validationSeed, 0, 1, EpisodePurpose::validation};
}

// The validation summary of one set of rewards.
ValidationRecord validationRecord(long episode, const std::vector<double>& rewards) {
  const RewardSummary summary = summarizeRewards(rewards);
  return ValidationRecord{episode, summary.mean, summary.median, summary.valid, summary.count};
}


// Rows of doubles as one tensor and back (learning curves, counters).
template <typename Row, typename ToArray>
torch::Tensor tableTensor(const std::vector<Row>& rows, int columns, ToArray toArray) {
  torch::Tensor t = torch::zeros({static_cast<long>(rows.size()), columns}, torch::kFloat64);
  auto a = t.accessor<double, 2>();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::vector<double> v = toArray(rows[i]);
    for (int j = 0; j < columns; ++j) a[static_cast<long>(i)][j] = v[static_cast<std::size_t>(j)];
  }
  return t;
}

torch::Tensor batchTensor(const PolicyBatch& b) {
  return torch::from_blob(const_cast<double*>(b.data()), {b.rows(), b.cols()}, torch::kFloat64).clone();
}

PolicyBatch batchFromTensor(const torch::Tensor& t) {
  const torch::Tensor c = t.to(torch::kFloat64).contiguous();
  return Eigen::Map<const PolicyBatch>(c.data_ptr<double>(), c.size(0), c.size(1));
}

}  // namespace

PolicyTrainer::PolicyTrainer(const PolicyTrainOptions& options, const PolicyEnvironment& environment,
                             RolloutEvaluator& rollouts)
    : options_(options),
      environment_(environment),
      rollouts_(rollouts),
      learner_((torch::set_num_threads(1), options.layout(environment.stateSize(), environment.actionSize())),
               options.learningRates, options.seed,
               options.actorStartAction(environment)),
      buffer_(environment.stateSize(), environment.actionSize(), options.bufferCapacity),
      demonstrations_(environment.stateSize(), environment.actionSize(), options.bufferCapacity),
      minibatchRandom_(episodeRandom(options.seed, 0, minibatchStream)),
      bestValidation_(-std::numeric_limits<double>::infinity()),
      start_(std::chrono::steady_clock::now()) {
  learner_.trainActorOutputsOnly(options_.actorTrainedActions);  // empty: every weight learns
  learner_.holdActorOutputs(options_.heldActions);              // empty: none held
  if (options_.actorAverageDecay > 0) learner_.averageActor(options_.actorAverageDecay);
  for (int i = 0; i < options_.validationPassages; ++i)
    validationTasks_.push_back(
        environment_.draw(options_.validationSeed, static_cast<std::uint64_t>(i), EpisodePurpose::validation));
}

double PolicyTrainer::secondsTrained() const {
  return secondsBefore_ +
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void PolicyTrainer::learnFrom(const std::vector<double>& state, const std::vector<double>& action,
                              double reward) {
  buffer_.add(state, action, reward);
  recentRewards_.push_back(reward);
  if (static_cast<long>(recentRewards_.size()) > recentCapacity(options_)) recentRewards_.erase(recentRewards_.begin());
  ++episode_;
  if (buffer_.size() >= options_.minibatch) {
    PolicyBatch s, a;
    Eigen::VectorXd r;
    for (int k = 0; k < options_.criticUpdatesPerEpisode; ++k) {
      buffer_.sample(options_.minibatch, minibatchRandom_, s, a, r);
      lossSum_ += learner_.updateCritic(s, a, r);
      ++lossCount_;
    }
    if (episode_ % options_.actorUpdateEvery == 0 && episode_ > options_.actorUpdatesFrom) {
      buffer_.sample(options_.minibatch, minibatchRandom_, s, a, r);
      learner_.updateActor(s, options_.actionBoundPenalty, options_.validityBarrier, imitationBatch());
    }
  }
  if (episode_ % options_.logEvery == 0) {
    const RewardSummary recent = summarizeRewards(recentRewards(options_.logEvery));
    LearningRecord record;
    record.episode = episode_;
    record.meanReward = recent.mean;
    record.validFraction = recent.count ? static_cast<double>(recent.valid) / recent.count : 0.0;
    record.criticLoss = lossCount_ ? lossSum_ / static_cast<double>(lossCount_) : 0.0;
    record.sigma = options_.noiseSigma(episode_ - 1);
    record.seconds = secondsTrained();
    learning_.push_back(record);
    lossSum_ = 0;
    lossCount_ = 0;
  }
}

std::vector<double> PolicyTrainer::recentRewards(long count) const {
  const long n = std::min<long>(count, static_cast<long>(recentRewards_.size()));
  return std::vector<double>(recentRewards_.rbegin(), recentRewards_.rbegin() + n);
}

Imitation PolicyTrainer::imitationBatch() {
  Imitation imitation;
  if (options_.imitationWeight <= 0 || demonstrations_.size() == 0) return imitation;
  PolicyBatch s, a;
  Eigen::VectorXd q;
  demonstrations_.sample(std::min<long>(options_.minibatch, demonstrations_.size()), minibatchRandom_, s, a, q);
  // Only where the demonstration beats what the critic expects of the actor's own action
  // (the Q filter of Nair et al., ICRA 2018): a demonstration the actor has overtaken, or
  // one from an older, worse actor, pulls no more.
  const Eigen::VectorXd own = learner_.value(s, learner_.act(s));
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < s.rows(); ++i)
    if (q(i) > own(i)) keep.push_back(i);
  imitation.states.resize(static_cast<Eigen::Index>(keep.size()), s.cols());
  imitation.actions.resize(static_cast<Eigen::Index>(keep.size()), a.cols());
  for (std::size_t k = 0; k < keep.size(); ++k) {
    imitation.states.row(static_cast<Eigen::Index>(k)) = s.row(keep[k]);
    imitation.actions.row(static_cast<Eigen::Index>(k)) = a.row(keep[k]);
  }
  imitation.weight = options_.imitationWeight;
  return imitation;
}

void PolicyTrainer::search(std::uint64_t index) {
  const EpisodeRange range{searchPassageSeed(options_.seed), index, 0};
  const EpisodeTask task = environment_.draw(range.seed, index, EpisodePurpose::training);
  const int m = environment_.actionSize();
  const PolicyBatch start = learner_.act(statesOf({task}, environment_.stateSize()));
  const BatchObjective objective = [&](const std::vector<Eigen::VectorXd>& points) {
    PolicyBatch actions(static_cast<Eigen::Index>(points.size()), m);
    for (std::size_t i = 0; i < points.size(); ++i) actions.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    return rollouts_.rewards(std::vector<EpisodeTask>(points.size(), task), actions, range);
  };
  // No pattern search: it builds one mesh at a time and would leave the other cores idle.
  const OptimizationResult result =
      searchActions(std::vector<double>(start.data(), start.data() + m), objective, options_.searchBudget,
                    episodeRandom(options_.seed, index, searchStream)(), 0.0);
  for (const Evaluation& e : result.history)
    buffer_.add(task.state, std::vector<double>(e.point.data(), e.point.data() + m), e.value);
  ++searches_;
  const double startQ = result.history.front().value;  // CMA-ES evaluates its start first
  if (startQ > invalidMeshQuality) {
    ++gainSearches_;
    searchGainSum_ += result.bestValue - startQ;
  }
  if (result.bestValue > invalidMeshQuality)
    demonstrations_.add(task.state, std::vector<double>(result.best.data(), result.best.data() + m), result.bestValue);
}

void PolicyTrainer::learnPending() {
  const PendingBatch batch = std::exchange(pending_, {});
  for (Eigen::Index i = 0; i < batch.actions.rows(); ++i) {
    const auto s = batch.states.row(i);
    const auto a = batch.actions.row(i);
    learnFrom(std::vector<double>(s.data(), s.data() + s.size()), std::vector<double>(a.data(), a.data() + a.size()),
              batch.rewards(i));
  }
}

void PolicyTrainer::runBatch() {
  const bool learnsDuringRollouts = options_.learnerSchedule == LearnerSchedule::duringNextRollouts;
  if (!learnsDuringRollouts) learnPending();  // none, unless started from a duringNextRollouts checkpoint
  const long first = builtEpisodes();
  // Past the end (duringNextRollouts, the last batch learnt): a whole batch, the one a longer
  // run builds here, so that a -resume to more episodes goes on as one straight run.
  const int count = static_cast<int>(first >= options_.episodes
                                         ? options_.batchEpisodes
                                         : std::min<long>(options_.batchEpisodes, options_.episodes - first));
  std::vector<EpisodeTask> tasks(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i)
    tasks[static_cast<std::size_t>(i)] =
        environment_.draw(options_.seed, static_cast<std::uint64_t>(first + i), EpisodePurpose::training);
  PolicyBatch states = statesOf(tasks, environment_.stateSize());
  PolicyBatch actions = learner_.act(states);
  if (!actions.allFinite()) throwDiverged();
  for (int i = 0; i < count; ++i) {
    std::mt19937_64 noise = episodeRandom(options_.seed, static_cast<std::uint64_t>(first + i), noiseStream);
    const double sigma = options_.noiseSigma(first + i);
    // (drawn only when asked for, so that runs without wide episodes keep their noise)
    const bool wide = options_.wideNoiseShare > 0 && uniform01(noise) < options_.wideNoiseShare;
    const auto& widened = options_.wideNoiseActions;
    const auto& held = options_.heldActions;
    for (int k = 0; k < actions.cols(); ++k) {
      const bool widen = wide && (widened.empty() || std::find(widened.begin(), widened.end(), k) != widened.end());
      // (drawn for a held action too, so that the others' noise is that of a run without it)
      const double step = (widen ? options_.wideNoiseSigma : sigma) * standardNormal(noise);
      if (std::find(held.begin(), held.end(), k) == held.end()) actions(i, k) = std::clamp(actions(i, k) + step, -1.0, 1.0);
    }
  }
  const EpisodeRange range{options_.seed, static_cast<std::uint64_t>(first)};
  const std::vector<double> rewards = learnsDuringRollouts
                                          ? rollouts_.rewardsWhile(tasks, actions, range, [&] { learnPending(); })
                                          : rollouts_.rewards(tasks, actions, range);
  pending_ = {std::move(states), std::move(actions), Eigen::Map<const Eigen::VectorXd>(rewards.data(), count)};
  if (!learnsDuringRollouts) learnPending();
}

ValidationRecord PolicyTrainer::validateAction(const std::vector<double>& action) const {
  if (static_cast<int>(action.size()) != environment_.actionSize())
    throw std::invalid_argument("validateAction: an action of " + std::to_string(action.size()) +
                                " values where the environment has " + std::to_string(environment_.actionSize()));
  const int n = static_cast<int>(validationTasks_.size());
  PolicyBatch actions(n, environment_.actionSize());
  for (int i = 0; i < n; ++i)
    actions.row(i) = Eigen::Map<const Eigen::RowVectorXd>(action.data(), environment_.actionSize());
  return validationRecord(0, rollouts_.rewards(validationTasks_, actions, validationRange(options_)));
}

ValidationRecord PolicyTrainer::validateCurrentPolicy() const {
  // One forward pass per state, as policyMesh makes it: a batched pass rounds differently
  // (about 1e-7 in float), enough to move a passage across a validity edge, and then the
  // logged validation would not be what the saved weights give (docs/policy.md).
  const PolicyBatch states = statesOf(validationTasks_, environment_.stateSize());
  PolicyBatch actions(states.rows(), environment_.actionSize());
  for (Eigen::Index i = 0; i < states.rows(); ++i) actions.row(i) = learner_.actDelivered(states.row(i));
  if (!actions.allFinite()) throwDiverged();
  return validationRecord(episode_, rollouts_.rewards(validationTasks_, actions, validationRange(options_)));
}

void PolicyTrainer::throwDiverged() const {
  // Before the batch's meshes and before the next checkpoint: the last one written is kept.
  const std::string problem = learner_.nonFiniteWeightProblem();
  throw std::runtime_error("the learner diverged by episode " + std::to_string(episode_) + ": " +
                           (problem.empty() ? "the actor's actions are not numbers" : problem) +
                           " (lower <actorLearningRate> or <criticLearningRate>; the last checkpoint is kept as "
                           "it was)");
}

void PolicyTrainer::validate() {
  if (!validationTasks_.empty()) validation_.push_back(validateCurrentPolicy());
}


bool PolicyTrainer::run(const std::atomic<bool>* stop, const Events& events) {
  start_ = std::chrono::steady_clock::now();
  while (episode_ < options_.episodes) {
    if (stop && stop->load()) return false;
    const long before = episode_;
    runBatch();
    if (options_.searchEvery > 0)
      for (long k = before / options_.searchEvery + 1; k <= episode_ / options_.searchEvery; ++k)
        search(static_cast<std::uint64_t>(k));
    const bool done = episode_ >= options_.episodes;
    // Due at the end, and when the batch passed a multiple of `every`.
    const auto due = [&](long every) { return done || episode_ / every > before / every; };
    if (due(options_.validationEvery)) {
      validate();
      if (!validation_.empty() && validation_.back().episode == episode_) {
        const ValidationRecord& latest = validation_.back();
        if (latest.meanReward > bestValidation_) {
          bestValidation_ = latest.meanReward;
          bestValid_ = latest.valid;
          if (options_.restoreBelowValidShare > 0) bestLearnerState_ = learner_.stateBytes();
          if (events.newBestValidation) events.newBestValidation(*this);
        } else if (!bestLearnerState_.empty() && latest.valid < options_.restoreBelowValidShare * bestValid_) {
          // A collapse (docs/policy.md "Collapses"): back to the best validation's learner.
          learner_.loadStateBytes(bestLearnerState_);
          learner_.holdActorOutputs(options_.heldActions);  // (a no-op: the state holds them)
          restores_.push_back(episode_);
          if (events.learnerRestored) events.learnerRestored(*this);
        }
      }
    }
    if (events.afterBatch) events.afterBatch(*this);
    if (due(options_.checkpointEvery) && events.checkpointDue)
      events.checkpointDue(*this);
  }
  return true;
}

void PolicyTrainer::saveCheckpoint(const std::filesystem::path& file) const {
  if (!learner_.nonFiniteWeightProblem().empty()) throwDiverged();  // the last checkpoint stays sound
  torch::serialize::OutputArchive archive;
  archive.write("format", c10::IValue(std::string(checkpointFormat)));
  archive.write("layout", c10::IValue(layoutText(learner_.layout())));
  archive.write("seed", c10::IValue(std::to_string(options_.seed)));
  archive.write("settings", c10::IValue(settingsText(options_)));
  std::ostringstream rng;
  rng << minibatchRandom_;
  archive.write("minibatchRandom", c10::IValue(rng.str()));
  const double counters[] = {static_cast<double>(episode_), bestValidation_, lossSum_,
                             static_cast<double>(lossCount_), secondsTrained(), static_cast<double>(searches_),
                             static_cast<double>(gainSearches_), searchGainSum_};
  archive.write("counters", torch::tensor(at::ArrayRef<double>(counters, 8), torch::kFloat64));
  const auto writeEpisodes = [&](const std::string& name, const PolicyBatch& s, const PolicyBatch& a,
                                 const Eigen::VectorXd& r) {
    archive.write(name + "States", batchTensor(s));
    archive.write(name + "Actions", batchTensor(a));
    archive.write(name + "Rewards", batchTensor(PolicyBatch(r)));
  };
  const auto writeBuffer = [&](const ReplayBuffer& buffer, const std::string& name) {
    PolicyBatch s, a;
    Eigen::VectorXd r;
    buffer.exportEpisodes(s, a, r);
    writeEpisodes(name, s, a, r);
  };
  writeBuffer(buffer_, "buffer");
  writeBuffer(demonstrations_, "demonstrations");
  // learnerSchedule duringNextRollouts: built, not yet learnt; at the run's end, the batch
  // built past it ("next": a -resume to more episodes learns it, a -startFrom drops it).
  if (pending_.actions.rows() > 0)
    writeEpisodes(episode_ >= options_.episodes ? "next" : "pending", pending_.states, pending_.actions,
                  pending_.rewards);
  archive.write("recentRewards", batchTensor(Eigen::Map<const PolicyBatch>(recentRewards_.data(),
                                                                           static_cast<Eigen::Index>(recentRewards_.size()), 1)));
  archive.write("learning", tableTensor(learning_, 6, [](const LearningRecord& x) {
                  return std::vector<double>{static_cast<double>(x.episode), x.meanReward, x.validFraction,
                                             x.criticLoss, x.sigma, x.seconds};
                }));
  archive.write("validation", tableTensor(validation_, 5, [](const ValidationRecord& x) {
                  return std::vector<double>{static_cast<double>(x.episode), x.meanReward, x.medianReward,
                                             static_cast<double>(x.valid), static_cast<double>(x.passages)};
                }));
  torch::serialize::OutputArchive networks;
  learner_.save(networks);
  archive.write("networks", networks);
  if (!bestLearnerState_.empty()) {
    archive.write("bestLearner", torch::from_blob(const_cast<char*>(bestLearnerState_.data()),
                                                  {static_cast<long>(bestLearnerState_.size())}, torch::kUInt8)
                                     .clone());
    archive.write("bestValid", torch::tensor(at::ArrayRef<double>{static_cast<double>(bestValid_)}, torch::kFloat64));
  }
  std::vector<double> restores(restores_.begin(), restores_.end());
  archive.write("restores", torch::tensor(at::ArrayRef<double>(restores), torch::kFloat64));
  saveArchiveAtomically(archive, file);
}

void PolicyTrainer::resume(const std::filesystem::path& file, bool sameSettings) {
  const std::string name = file.string();
  if (!std::filesystem::exists(file)) throw InputError(name, 0, "no checkpoint to resume from");
  const auto corrupt = [&](const std::string& what) { return InputError(name, 0, "corrupt checkpoint: " + what); };
  if (const std::string problem = zipChecksumProblem(name); !problem.empty())
    throw InputError(name, 0, problem + " (expected a checkpoint policyTrain wrote)");
  try {
    torch::serialize::InputArchive archive;
    archive.load_from(name);
    c10::IValue value;
    archive.read("format", value);
    if (!value.isString() || value.toStringRef() != checkpointFormat)
      throw InputError(name, 0, "not a policyTrain checkpoint (format line missing or different)");
    archive.read("layout", value);
    // A continuation (-startFrom) may switch between the two validity critics: they hold the
    // same tensors and differ only in whether the quality output is read through a sigmoid.
    NetworkLayout switched = learner_.layout();
    const bool mayBeSwitched = !sameSettings && hasValidity(switched.critic);
    switched.critic = switched.critic == CriticModel::validityAndQuality ? CriticModel::validityAndBoundedQuality
                                                                          : CriticModel::validityAndQuality;
    const bool acceptable = value.toStringRef() == layoutText(learner_.layout()) ||
                            (mayBeSwitched && value.toStringRef() == layoutText(switched));
    if (!acceptable)
      throw InputError(name, 0, "the checkpoint's networks are " + value.toStringRef() +
                                    " (state, action, [hidden], slope[, critic model]), this run's " +
                                    layoutText(learner_.layout()));
    archive.read("seed", value);
    if (sameSettings && value.toStringRef() != std::to_string(options_.seed))
      throw InputError(name, 0, "the checkpoint was written with seed " + value.toStringRef() +
                                    ", this run has seed " + std::to_string(options_.seed));
    // Checkpoints before the settings were recorded have none to compare.
    if (sameSettings && archive.try_read("settings", value)) {
      const std::string difference = firstDifference(value.toStringRef(), options_);
      if (!difference.empty())
        throw InputError(name, 0, "the checkpoint's run had other settings (" + difference +
                                      "): resume with its policyTrainDict, or start afresh");
    }

    // Everything is read into locals first, so a failure leaves the trainer as it was.
    archive.read("minibatchRandom", value);
    std::istringstream rngText(value.toStringRef());
    std::mt19937_64 rng;
    rngText >> rng;
    if (!rngText) throw corrupt("the random generator's state does not parse");
    torch::Tensor counters, learning, validation;
    archive.read("counters", counters);
    archive.read("learning", learning);
    archive.read("validation", validation);
    const auto table = [&](const torch::Tensor& t, long columns, const std::string& what) {
      if (t.scalar_type() != torch::kFloat64 || t.dim() != 2 || t.size(1) != columns)
        throw corrupt(what + " has the wrong shape or type");
    };
    // Checkpoints from before the searches have 5 counters, no demonstrations and no
    // recent rewards (the buffer's newest were all episodes then).
    if (counters.scalar_type() != torch::kFloat64 || counters.dim() != 1 ||
        (counters.size(0) != 5 && counters.size(0) != 8))
      throw corrupt("the counters have the wrong shape or type");
    table(learning, 6, "the learning curve");
    table(validation, 5, "the validation curve");
    // Episodes stored as three tensors; false when optional and absent.
    const auto readEpisodes = [&](const std::string& prefix, const std::string& what, bool optional,
                                  PendingBatch& episodes) {
      torch::Tensor s, a, r;
      if (optional && !archive.try_read(prefix + "States", s)) return false;
      if (!optional) archive.read(prefix + "States", s);
      archive.read(prefix + "Actions", a);
      archive.read(prefix + "Rewards", r);
      table(s, learner_.layout().stateSize, what + "'s states");
      table(a, learner_.layout().actionSize, what + "'s actions");
      table(r, 1, what + "'s rewards");
      if (a.size(0) != s.size(0) || r.size(0) != s.size(0))
        throw corrupt(what + " has parts of unequal length");
      episodes = {batchFromTensor(s), batchFromTensor(a), batchFromTensor(r).col(0)};
      return true;
    };
    const auto readBuffer = [&](const std::string& prefix, const std::string& what, bool optional) {
      ReplayBuffer buffer(learner_.layout().stateSize, learner_.layout().actionSize, options_.bufferCapacity);
      PendingBatch episodes;
      if (!readEpisodes(prefix, what, optional, episodes)) return buffer;
      if (episodes.actions.rows() > options_.bufferCapacity)
        throw corrupt(what + " holds " + std::to_string(episodes.actions.rows()) + " rows, more than <bufferCapacity>");
      buffer.importEpisodes(episodes.states, episodes.actions, episodes.rewards);
      return buffer;
    };
    ReplayBuffer buffer = readBuffer("buffer", "the buffer", false);
    ReplayBuffer demonstrations = readBuffer("demonstrations", "the demonstrations", true);
    // The batch built but not yet learnt (learnerSchedule duringNextRollouts), in order; or
    // the one built past the end of a finished run, which only a -resume continues (a
    // -startFrom's run builds its first batch under its own settings).
    PendingBatch pending;
    if (!readEpisodes("pending", "the pending batch", true, pending) && sameSettings)
      readEpisodes("next", "the batch built past the run's end", true, pending);
    std::vector<double> recent;
    torch::Tensor recentTensor;
    if (archive.try_read("recentRewards", recentTensor)) {
      table(recentTensor, 1, "the recent rewards");
      const PolicyBatch column = batchFromTensor(recentTensor);
      recent.assign(column.data(), column.data() + column.size());
    } else {
      recent = buffer.recentRewards(recentCapacity(options_));
      std::reverse(recent.begin(), recent.end());
    }
    while (static_cast<long>(recent.size()) > recentCapacity(options_)) recent.erase(recent.begin());
    std::vector<LearningRecord> learningRecords;
    const auto l = learning.accessor<double, 2>();
    for (long i = 0; i < learning.size(0); ++i)
      learningRecords.push_back(LearningRecord{static_cast<long>(l[i][0]), l[i][1], l[i][2], l[i][3], l[i][4], l[i][5]});
    std::vector<ValidationRecord> validationRecords;
    const auto v = validation.accessor<double, 2>();
    for (long i = 0; i < validation.size(0); ++i)
      validationRecords.push_back(ValidationRecord{static_cast<long>(v[i][0]), v[i][1], v[i][2],
                                                   static_cast<int>(v[i][3]), static_cast<int>(v[i][4])});
    const auto c = counters.accessor<double, 1>();
    const long learnt = static_cast<long>(c[0]);
    // (A finished run resumed at its own length has nothing left to run and keeps its batch.)
    if (pending.actions.rows() > 0 && learnt < options_.episodes && learnt + pending.actions.rows() > options_.episodes)
      throw InputError(name, 0, "the checkpoint has built " + std::to_string(learnt + pending.actions.rows()) +
                                    " episodes (" + std::to_string(learnt) + " learnt): ask for at least that many "
                                    "<episodes>, not " + std::to_string(options_.episodes));
    // The learner at the best validation and the restores so far (absent in checkpoints
    // written before restoreBelowValidShare existed).
    std::string bestState;
    int bestValid = 0;
    torch::Tensor bestTensor, bestValidTensor, restoresTensor;
    if (archive.try_read("bestLearner", bestTensor)) {
      archive.read("bestValid", bestValidTensor);
      if (bestTensor.scalar_type() != torch::kUInt8 || bestTensor.dim() != 1 ||
          bestValidTensor.scalar_type() != torch::kFloat64 || bestValidTensor.numel() != 1)
        throw corrupt("the best validation's learner has the wrong shape or type");
      const auto* bytes = static_cast<const char*>(bestTensor.contiguous().data_ptr());
      bestState.assign(bytes, bytes + bestTensor.size(0));
      bestValid = static_cast<int>(bestValidTensor.item<double>());
    }
    std::vector<long> restoreEpisodes;
    if (archive.try_read("restores", restoresTensor)) {
      if (restoresTensor.scalar_type() != torch::kFloat64 || restoresTensor.dim() != 1)
        throw corrupt("the restores have the wrong shape or type");
      const auto r = restoresTensor.accessor<double, 1>();
      for (long i = 0; i < restoresTensor.size(0); ++i) restoreEpisodes.push_back(static_cast<long>(r[i]));
    }
    // The best validation's learner is loaded first, only to check it (it parses and its
    // weights are finite: it becomes the shipped policy); the checkpoint's own networks,
    // loaded next, replace every part of it.
    if (!bestState.empty()) {
      try {
        learner_.loadStateBytes(bestState);
      } catch (const std::exception& e) {
        throw corrupt(std::string("the best validation's learner: ") + e.what());
      }
    }
    torch::serialize::InputArchive networks;
    archive.read("networks", networks);
    learner_.load(networks);  // last: it can fail too, and then the run ends anyway
    learner_.holdActorOutputs(options_.heldActions);  // (a no-op on a checkpoint of this run)

    episode_ = learnt;
    bestValidation_ = c[1];
    lossSum_ = c[2];
    lossCount_ = static_cast<long>(c[3]);
    secondsBefore_ = c[4];
    const bool searched = counters.size(0) == 8;
    searches_ = searched ? static_cast<long>(c[5]) : 0;
    gainSearches_ = searched ? static_cast<long>(c[6]) : 0;
    searchGainSum_ = searched ? c[7] : 0.0;
    minibatchRandom_ = rng;
    buffer_ = std::move(buffer);
    demonstrations_ = std::move(demonstrations);
    pending_ = std::move(pending);
    recentRewards_ = std::move(recent);
    learning_ = std::move(learningRecords);
    validation_ = std::move(validationRecords);
    bestLearnerState_ = std::move(bestState);
    bestValid_ = bestValid;
    restores_ = std::move(restoreEpisodes);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    std::string what = e.what();
    what = what.substr(0, what.find('\n'));
    throw InputError(name, 0, "corrupt or unreadable checkpoint (" + what + ")");
  }
}

void PolicyTrainer::startActorFrom(const Policy& policy, const PolicyStateScaling& scaling) {
  const std::string file = policy.actorFile().string();
  if (policy.memberCount() != 1)
    throw InputError(file, 0, "the actor's start must be a single policy, not an ensemble of " +
                                  std::to_string(policy.memberCount()));
  const PolicyStateScaling& theirs = policy.stateScaling();
  if (theirs.lower != scaling.lower || theirs.upper != scaling.upper || theirs.logarithmic != scaling.logarithmic)
    throw InputError(file, 0, "the policy scales the state otherwise than this run (<edgeRadii>, etc/bladeParameterRange.xml)");
  try {
    learner_.startActorFrom(policy.actorFile(), policy.layout());
    learner_.holdActorOutputs(options_.heldActions);
  } catch (const std::invalid_argument& e) {
    throw InputError(file, 0, e.what());
  }
}

}  // namespace passageMesh
