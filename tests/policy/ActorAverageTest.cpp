// The Polyak-averaged actor (ActorCritic::averageActor, PolicyTrainOptions::
// actorAverageDecay): it trails the learning actor, it leaves the learning untouched bit for
// bit, it is what a trainer validates and saves, and checkpoints keep it.
#include <gtest/gtest.h>

#include <string>

#include "../TestFiles.hpp"
#include "PolicyTrainerTestRuns.hpp"
#include "passageMesh/policy/ActorCritic.hpp"
#include "passageMesh/policy/PolicyNetworks.hpp"
#include "passageMesh/policy/PolicyTrainer.hpp"
#include "passageMesh/policy/ToyEnvironment.hpp"

using namespace passageMesh;
using testRuns::fingerprint;
using testRuns::smallRun;

namespace {

const NetworkLayout layout{3, 3, {16, 16}, 0.01};

PolicyBatch someStates() {
  PolicyBatch s(4, 3);
  s << -0.5, 0.2, 0.9, 0.1, -0.8, 0.3, 0.7, 0.7, -0.2, 0.0, 0.5, -0.6;
  return s;
}

// `steps` actor steps pulling the actions of someStates() to fixed targets.
void train(ActorCritic& learner, int steps) {
  PolicyBatch target(4, 3);
  target << 0.6, -0.4, 0.5, -0.7, 0.2, -0.5, 0.3, 0.8, 0.4, -0.1, -0.9, -0.3;
  for (int step = 0; step < steps; ++step) learner.updateActor(someStates(), 0, 0, Imitation{someStates(), target, 10.0});
}

}  // namespace

TEST(ActorAverage, TheAverageStartsAtTheActorAndLeavesTheLearningAsItIs) {
  ActorCritic plain(layout, {1e-2, 1e-3}, 3, {0.1, -0.2, 0.25});
  const torch::Tensor plainDraw = torch::rand({3});  // where LibTorch's generator stands after the networks
  ActorCritic averaged(layout, {1e-2, 1e-3}, 3, {0.1, -0.2, 0.25});
  averaged.averageActor(0.99);
  EXPECT_TRUE(torch::equal(torch::rand({3}), plainDraw)) << "making the average drew from the generator";
  EXPECT_TRUE(averaged.averagesActor());
  EXPECT_FALSE(plain.averagesActor());
  const PolicyBatch start = averaged.act(someStates());
  EXPECT_EQ(averaged.actDelivered(someStates()), start);
  EXPECT_EQ(plain.actDelivered(someStates()), plain.act(someStates()));

  train(plain, 300);
  train(averaged, 300);
  EXPECT_EQ(averaged.act(someStates()), plain.act(someStates()));  // bit for bit
  const PolicyBatch learnt = averaged.act(someStates());
  const PolicyBatch delivered = averaged.actDelivered(someStates());
  // After 300 steps at decay 0.99 the average has forgotten 0.99^300 = 5 % of the start
  // weights; it trails the actor, so it lies between, nearer the actor.
  const double moved = (learnt - start).norm(), behind = (delivered - learnt).norm();
  EXPECT_GT(moved, 0.3);
  EXPECT_GT(behind, 1e-4 * moved);
  EXPECT_LT(behind, 0.5 * moved);
  EXPECT_LT((delivered - start).norm(), moved);

  // A decay near 1 keeps the start.
  ActorCritic slow(layout, {1e-2, 1e-3}, 3, {0.1, -0.2, 0.25});
  slow.averageActor(1 - 1e-9);
  train(slow, 300);
  EXPECT_LT((slow.actDelivered(someStates()) - start).cwiseAbs().maxCoeff(), 1e-5);
  EXPECT_THROW(slow.averageActor(1.0), std::invalid_argument);
  EXPECT_THROW(slow.averageActor(0.0), std::invalid_argument);
}

TEST(ActorAverage, HeldOutputsStayHeldInTheAverage) {
  ActorCritic learner(layout, {1e-2, 1e-3}, 3, {0.1, -0.2, 0.25});
  learner.holdActorOutputs({2});
  learner.averageActor(0.9);
  const double held = learner.act(someStates())(0, 2);
  train(learner, 200);
  PolicyBatch far = 30.0 * someStates();
  EXPECT_EQ(learner.actDelivered(far).col(2), PolicyBatch::Constant(4, 1, held));
  EXPECT_NE(learner.actDelivered(far).col(0), learner.act(far).col(0));
}

TEST(ActorAverage, SavingAndLoadingKeepsTheAverageAndAStateWithoutOneStartsItAtTheActor) {
  ActorCritic learner(layout, {1e-2, 1e-3}, 3, {0.1, -0.2, 0.25});
  learner.averageActor(0.95);
  train(learner, 100);
  // Through bytes, as PolicyTrainer keeps the best validation's learner.
  ActorCritic loaded(layout, {1e-2, 1e-3}, 4);  // other weights until loaded
  loaded.averageActor(0.95);
  loaded.loadStateBytes(learner.stateBytes());
  EXPECT_EQ(loaded.actDelivered(someStates()), learner.actDelivered(someStates()));
  EXPECT_EQ(loaded.act(someStates()), learner.act(someStates()));

  ActorCritic plain(layout, {1e-2, 1e-3}, 3, {0.1, -0.2, 0.25});
  train(plain, 100);
  loaded.loadStateBytes(plain.stateBytes());
  EXPECT_EQ(loaded.actDelivered(someStates()), plain.act(someStates()));
}

// In a run: the learning is that of a run without averaging, the validations and the saved
// policy are the averaged actor's, and a resumed run ends with the same average bit for bit.
TEST(ActorAverage, ATrainerValidatesAndSavesTheAverageAndResumesItBitForBit) {
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(1);
  PolicyTrainer plain(smallRun(300), toy, rollouts);
  ASSERT_TRUE(plain.run(nullptr, {}));
  PolicyTrainOptions run = smallRun(300);
  run.actorAverageDecay = 0.9;
  PolicyTrainer straight(run, toy, rollouts);
  ASSERT_TRUE(straight.run(nullptr, {}));
  EXPECT_EQ(fingerprint(straight.learner(), 24, 8), fingerprint(plain.learner(), 24, 8));
  ASSERT_EQ(straight.learningCurve().size(), plain.learningCurve().size());
  for (std::size_t i = 0; i < plain.learningCurve().size(); ++i)
    EXPECT_EQ(straight.learningCurve()[i].meanReward, plain.learningCurve()[i].meanReward);
  ASSERT_EQ(straight.validationCurve().size(), 3u);
  EXPECT_NE(straight.validationCurve().back().meanReward, plain.validationCurve().back().meanReward);

  // The policy files hold the averaged actor: they give the validation's mean reward.
  EXPECT_EQ(testRuns::meanRewardThroughPolicyFiles(straight.learner(), toy, run, "actorAverageTrainer"),
            straight.validationCurve().back().meanReward);

  const auto file = testData::tempFolder("actorAverageTrainer") / "checkpoint.pt";
  {
    PolicyTrainer first(run, toy, rollouts);
    ASSERT_TRUE(testRuns::runToFirstCheckpoint(first, file));
    ASSERT_EQ(first.episode(), 64);
  }
  PolicyTrainer resumed(run, toy, rollouts);
  resumed.resume(file);
  ASSERT_TRUE(resumed.run(nullptr, {}));
  const PolicyBatch states = testRuns::fingerprintStates(24);
  EXPECT_EQ(resumed.learner().actDelivered(states), straight.learner().actDelivered(states));
  EXPECT_EQ(resumed.validationCurve().back().meanReward, straight.validationCurve().back().meanReward);
}
