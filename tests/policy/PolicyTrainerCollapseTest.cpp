// A collapse undone: a validation meshing fewer than PolicyTrainOptions::
// restoreBelowValidShare of the best validation's passages takes the learner back to its
// state at that best, and a checkpoint keeps that state for -resume.
#include "passageMesh/policy/PolicyTrainer.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <memory>

#include "../TestFiles.hpp"
#include "PolicyTrainerTestRuns.hpp"
#include "passageMesh/policy/ToyEnvironment.hpp"

using namespace passageMesh;
using testRuns::fingerprint;
using testRuns::smallRun;

namespace {

// The toy whose every reward is -1 while `broken` is set: a collapse on demand (the
// validation passages, drawn when the trainer is made, see the switch too).
class BreakableToy final : public PolicyEnvironment {
 public:
  explicit BreakableToy(const ToyEnvironment& toy) : toy_(toy) {}
  int stateSize() const override { return toy_.stateSize(); }
  int actionSize() const override { return toy_.actionSize(); }
  EpisodeTask draw(std::uint64_t seed, std::uint64_t episode, EpisodePurpose purpose) const override {
    EpisodeTask task = toy_.draw(seed, episode, purpose);
    task.reward = [inner = task.reward, broken = broken_](const std::vector<double>& action) {
      return broken->load() ? -1.0 : inner(action);
    };
    return task;
  }
  void setBroken(bool broken) { broken_->store(broken); }

 private:
  const ToyEnvironment& toy_;
  std::shared_ptr<std::atomic<bool>> broken_ = std::make_shared<std::atomic<bool>>(false);
};

constexpr long breakAfter = 250;  // every reward -1 from the batch after this episode on

}  // namespace

TEST(PolicyTrainerCollapse, AValidationWithTooFewValidMeshesTakesTheLearnerBackToTheBest) {
  const ToyEnvironment toy(24, 8, 3);
  for (const double share : {0.5, 0.0}) {
    SCOPED_TRACE(share);
    BreakableToy environment(toy);
    PolicyTrainOptions run = smallRun(400);  // validations after the batches passing 100, 200, 300, 400: 112, 208, 304, 400
    run.restoreBelowValidShare = share;
    ThreadRollouts rollouts(1);
    PolicyTrainer trainer(run, environment, rollouts);
    std::pair<PolicyBatch, Eigen::VectorXd> best;
    long bestEpisode = 0, restoredEvents = 0;
    PolicyTrainer::Events events;
    events.newBestValidation = [&](const PolicyTrainer& t) {
      best = fingerprint(t.learner(), 24, 8);
      bestEpisode = t.episode();
    };
    events.afterBatch = [&](const PolicyTrainer& t) {
      if (t.episode() >= breakAfter) environment.setBroken(true);
    };
    events.learnerRestored = [&](const PolicyTrainer&) { ++restoredEvents; };
    ASSERT_TRUE(trainer.run(nullptr, events));
    ASSERT_EQ(trainer.validationCurve().size(), 4u);
    EXPECT_EQ(trainer.validationCurve()[1].valid, 5);  // before the break: every passage meshes
    EXPECT_EQ(trainer.validationCurve()[2].valid, 0);
    EXPECT_LE(bestEpisode, 208);
    const auto last = fingerprint(trainer.learner(), 24, 8);
    if (share > 0) {
      EXPECT_EQ(trainer.restores(), (std::vector<long>{304, 400}));
      EXPECT_EQ(restoredEvents, 2);
      EXPECT_EQ(last.first, best.first);  // bit for bit: the state is loaded, not relearnt
      EXPECT_EQ(last.second, best.second);
    } else {
      EXPECT_TRUE(trainer.restores().empty());
      EXPECT_EQ(restoredEvents, 0);
      EXPECT_NE(last.first, best.first);  // the broken episodes moved it
    }
  }
}

TEST(PolicyTrainerCollapse, ACheckpointKeepsTheBestValidationsLearnerForTheRestore) {
  const ToyEnvironment toy(24, 8, 3);
  PolicyTrainOptions run = smallRun(400);
  run.checkpointEvery = 256;  // after the best validation (112 or 208), before the break is seen
  ThreadRollouts rollouts(1);
  const auto breakAt = [](BreakableToy& environment) {
    return [&environment](const PolicyTrainer& t) {
      if (t.episode() >= breakAfter) environment.setBroken(true);
    };
  };
  BreakableToy straightToy(toy);
  PolicyTrainer straight(run, straightToy, rollouts);
  PolicyTrainer::Events straightEvents;
  straightEvents.afterBatch = breakAt(straightToy);
  ASSERT_TRUE(straight.run(nullptr, straightEvents));
  ASSERT_EQ(straight.restores(), (std::vector<long>{304, 400}));

  const auto file = testData::tempFolder("policyTrainerCollapse") / "checkpoint.pt";
  BreakableToy firstToy(toy);
  {
    PolicyTrainer first(run, firstToy, rollouts);
    std::atomic<bool> stop{false};
    PolicyTrainer::Events events;
    events.afterBatch = breakAt(firstToy);
    events.checkpointDue = [&](const PolicyTrainer& t) {
      t.saveCheckpoint(file);
      stop = true;  // as if killed right after the checkpoint
    };
    ASSERT_FALSE(first.run(&stop, events));
    ASSERT_EQ(first.episode(), 256);
  }
  BreakableToy resumedToy(toy);
  resumedToy.setBroken(true);  // as the first run left its episodes after 256
  PolicyTrainer resumed(run, resumedToy, rollouts);
  resumed.resume(file);
  ASSERT_TRUE(resumed.run(nullptr, {}));
  EXPECT_EQ(resumed.restores(), straight.restores());
  EXPECT_EQ(fingerprint(resumed.learner(), 24, 8), fingerprint(straight.learner(), 24, 8));
}
