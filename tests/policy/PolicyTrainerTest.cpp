// The training loop: checkpoints resume bit for bit, and the weights do not depend on
// how many threads build the meshes.
#include "passageMesh/policy/PolicyTrainer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "../TestFiles.hpp"
#include "PolicyTrainerTestRuns.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/policy/Policy.hpp"
#include "passageMesh/policy/ToyEnvironment.hpp"

using namespace passageMesh;
using testRuns::fingerprint;
using testRuns::smallRun;

// Both critic models, on a toy with failures (-1) so that the validity network learns too;
// with searches and imitation (their demonstrations and counters are in the checkpoint);
// and with the learner beside the next batch's rollouts (the checkpoint holds a batch built
// but not yet learnt).
TEST(PolicyTrainer, ResumingFromACheckpointGivesTheSameWeightsBitForBit) {
  for (const std::string variant : {"reward", "validityAndQuality", "searches", "duringNextRollouts"}) {
    SCOPED_TRACE(variant);
    const ToyEnvironment toy(24, 8, 3, 0.05);
    PolicyTrainOptions run = smallRun(300);
    if (variant == "searches") {
      run.searchEvery = 48;  // not a multiple of the batch: one search follows episode 48's batch
      run.searchBudget = 12;
      run.imitationWeight = 1;
    } else if (variant == "duringNextRollouts") {
      run.learnerSchedule = LearnerSchedule::duringNextRollouts;
    } else {
      run.criticModel = criticModelNamed(variant);
    }
    ThreadRollouts rollouts(1);
    PolicyTrainer straight(run, toy, rollouts);
    ASSERT_TRUE(straight.run(nullptr, {}));

    const auto file = testData::tempFolder("policyTrainer" + variant) / "checkpoint.pt";
    {
      PolicyTrainer first(run, toy, rollouts);
      ASSERT_TRUE(testRuns::runToFirstCheckpoint(first, file));
      EXPECT_EQ(first.episode(), 64);
    }
    PolicyTrainer resumed(run, toy, rollouts);
    resumed.resume(file);
    EXPECT_EQ(resumed.episode(), 64);
    ASSERT_TRUE(resumed.run(nullptr, {}));

    EXPECT_EQ(fingerprint(resumed.learner(), 24, 8), fingerprint(straight.learner(), 24, 8));
    ASSERT_EQ(resumed.learningCurve().size(), straight.learningCurve().size());
    for (std::size_t i = 0; i < resumed.learningCurve().size(); ++i)
      EXPECT_EQ(resumed.learningCurve()[i].meanReward, straight.learningCurve()[i].meanReward);
    ASSERT_EQ(resumed.validationCurve().size(), 3u);
    EXPECT_EQ(resumed.validationCurve().back().meanReward, straight.validationCurve().back().meanReward);
    EXPECT_EQ(resumed.bestValidation(), straight.bestValidation());
    EXPECT_EQ(resumed.searchSummary().searches, straight.searchSummary().searches);
    EXPECT_EQ(resumed.searchSummary().meanGain, straight.searchSummary().meanGain);
    EXPECT_EQ(resumed.demonstrations().size(), straight.demonstrations().size());
    if (variant == "validityAndQuality") {
      const std::vector<double> rewards = straight.buffer().recentRewards(300);
      EXPECT_GT(std::count(rewards.begin(), rewards.end(), -1.0), 10) << "the toy gave too few failures";
    }
  }
}

// The message of resuming `file` with these options; "accepted" when it was.
static std::string resumeError(const PolicyTrainOptions& options, const std::filesystem::path& file) {
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(1);
  PolicyTrainer trainer(options, toy, rollouts);
  try {
    trainer.resume(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

// The baseline's fixed action is read as the environment's size: a shorter one is refused
// (it was read past its end).
TEST(PolicyTrainer, ValidatingAFixedActionOfTheWrongSizeIsRefused) {
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(1);
  const PolicyTrainer trainer(smallRun(64), toy, rollouts);
  EXPECT_THROW(trainer.validateAction(std::vector<double>(7, 0.0)), std::invalid_argument);
  EXPECT_THROW(trainer.validateAction(std::vector<double>(9, 0.0)), std::invalid_argument);
  const ValidationRecord fine = trainer.validateAction(std::vector<double>(8, 0.0));
  EXPECT_GT(fine.passages, 0);
}

TEST(PolicyTrainer, ACheckpointOfAnotherRunOrACorruptFileIsRefusedWithItsName) {
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(1);
  const auto dir = testData::tempFolder("policyTrainerBad");
  PolicyTrainer trainer(smallRun(64), toy, rollouts);
  trainer.run(nullptr, {});
  trainer.saveCheckpoint(dir / "good.pt");

  PolicyTrainOptions changed = smallRun(64);
  changed.seed = 12;
  EXPECT_NE(resumeError(changed, dir / "good.pt").find("seed 11"), std::string::npos);
  changed = smallRun(64);
  changed.noiseAmplitude = 0.2;
  const std::string noise = resumeError(changed, dir / "good.pt");
  EXPECT_NE(noise.find("<noiseAmplitude> was 0.25, is 0.20000000000000001"), std::string::npos) << noise;
  changed = smallRun(64);
  changed.hidden = {16, 8};
  EXPECT_NE(resumeError(changed, dir / "good.pt").find("networks are"), std::string::npos);
  changed = smallRun(64);
  changed.criticModel = CriticModel::validityAndQuality;
  const std::string otherCritic = resumeError(changed, dir / "good.pt");
  EXPECT_NE(otherCritic.find("networks are 24 8 [16 16] 0.01 (state"), std::string::npos) << otherCritic;
  EXPECT_NE(otherCritic.find("this run's 24 8 [16 16] 0.01 validityAndQuality"), std::string::npos) << otherCritic;
  {
    PolicyTrainer split(changed, toy, rollouts);
    split.run(nullptr, {});
    split.saveCheckpoint(dir / "split.pt");
  }
  const std::string backToReward = resumeError(smallRun(64), dir / "split.pt");
  EXPECT_NE(backToReward.find("networks are 24 8 [16 16] 0.01 validityAndQuality"), std::string::npos) << backToReward;
  EXPECT_EQ(backToReward.find('\n'), std::string::npos) << backToReward;
  changed = smallRun(640);  // more episodes or other threads: the same run
  changed.threads = 2;
  EXPECT_EQ(resumeError(changed, dir / "good.pt"), "accepted");

  std::filesystem::copy_file(dir / "good.pt", dir / "flipped.pt");
  testData::flipATensorByte(dir / "flipped.pt");
  const std::string flipped = resumeError(smallRun(64), dir / "flipped.pt");
  EXPECT_NE(flipped.find("flipped.pt: member '"), std::string::npos) << flipped;
  EXPECT_NE(flipped.find("' does not match its checksum (the file is corrupt)"), std::string::npos) << flipped;

  std::ofstream(dir / "corrupt.pt") << "not a checkpoint";
  const std::string corrupt = resumeError(smallRun(64), dir / "corrupt.pt");
  EXPECT_NE(corrupt.find("corrupt.pt"), std::string::npos) << corrupt;
  EXPECT_EQ(corrupt.find('\n'), std::string::npos) << corrupt;
}

TEST(PolicyTrainer, PassageTrainingGivesTheSameWeightsOnOneOrTwoThreads) {
  const PassageEnvironment passages;
  PolicyTrainOptions o = smallRun(48);  // three batches: the learner starts in the second
  o.validationPassages = 4;
  o.validationEvery = 48;
  o.noiseStartSigma = 0.3;  // some valid meshes among them
  std::vector<std::pair<PolicyBatch, Eigen::VectorXd>> weights;
  for (const LearnerSchedule schedule : {LearnerSchedule::afterRollouts, LearnerSchedule::duringNextRollouts}) {
    SCOPED_TRACE(nameOf(schedule));
    o.learnerSchedule = schedule;
    ThreadRollouts one(1), two(2);
    PolicyTrainer a(o, passages, one), b(o, passages, two);
    ASSERT_TRUE(a.run(nullptr, {}));
    ASSERT_TRUE(b.run(nullptr, {}));
    EXPECT_EQ(a.episode(), 48);
    EXPECT_EQ(a.buffer().size(), 48);
    weights.push_back(fingerprint(a.learner(), policyStateSize, policyActionSize));
    EXPECT_EQ(weights.back(), fingerprint(b.learner(), policyStateSize, policyActionSize));
    ASSERT_EQ(a.validationCurve().size(), 1u);
    EXPECT_EQ(a.validationCurve()[0].meanReward, b.validationCurve()[0].meanReward);
    std::vector<double> rewards = a.buffer().recentRewards(48);
    for (double r : rewards) EXPECT_TRUE(r == -1.0 || (r >= 0.0 && r <= 1.0)) << r;
    EXPECT_GT(std::count_if(rewards.begin(), rewards.end(), [](double r) { return r > 0; }), 0);
  }
  // The third batch's actions came from another actor (before the second batch's updates),
  // so the two schedules train other weights.
  EXPECT_NE(weights[0], weights[1]);
}

// The validation curve scores what policyMesh will do with the weights: one forward pass
// per state. A batched pass rounds differently in float (about 1e-7), and on a mesh that
// can flip a passage across a validity edge (a resumed run logged 0.4996 for weights
// whose one-state passes score 0.4923, docs/policy-history.md); the toy reward, continuous in the
// action, sees any such difference.
TEST(PolicyTrainer, TheValidationScoresTheActionsOfOneStateForwardPasses) {
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(1);
  PolicyTrainOptions o = smallRun(64);
  o.hidden = {512, 256, 256, 128};  // the paper's networks: batching changes their rounding
  o.validationEvery = 32;
  o.validationPassages = 50;
  // The mean reward of the trainer's weights through the files, as policyMesh reads them.
  const auto throughPolicyFiles = [&](const PolicyTrainer& trainer) {
    return testRuns::meanRewardThroughPolicyFiles(trainer.learner(), toy, o, "validationOneState");
  };
  // Stopped at episode 48, between the validations at 32 and 64 (as by Ctrl-C).
  PolicyTrainer trainer(o, toy, rollouts);
  std::atomic<bool> stop{false};
  PolicyTrainer::Events events;
  events.afterBatch = [&](const PolicyTrainer& t) { stop = t.episode() >= 48; };
  ASSERT_FALSE(trainer.run(&stop, events));
  ASSERT_EQ(trainer.episode(), 48);
  ASSERT_EQ(trainer.validationCurve().size(), 1u);
  EXPECT_EQ(trainer.validationCurve()[0].episode, 32);
  const ValidationRecord now = trainer.validateCurrentPolicy();
  EXPECT_EQ(now.episode, 48);
  EXPECT_EQ(now.passages, o.validationPassages);
  EXPECT_EQ(now.meanReward, throughPolicyFiles(trainer));
  EXPECT_EQ(trainer.validationCurve().size(), 1u);  // the curve is left as it was
  // Run to the end: the curve's last point is the final weights' validation.
  ASSERT_TRUE(trainer.run(nullptr, {}));
  ASSERT_EQ(trainer.validationCurve().size(), 2u);
  EXPECT_EQ(trainer.validationCurve()[1].episode, 64);
  EXPECT_EQ(trainer.validationCurve()[1].meanReward, throughPolicyFiles(trainer));
  EXPECT_EQ(trainer.validateCurrentPolicy().meanReward, trainer.validationCurve()[1].meanReward);
}

// A search: CMA-ES from the actor's action on a passage of its own stream; all its meshes
// enter the replay buffer (not the learning curve's episodes), its best becomes a
// demonstration no worse than the actor's own action.
TEST(PolicyTrainer, SearchesFeedTheBufferAndLeaveDemonstrationsAtLeastAsGoodAsTheActor) {
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(2);
  PolicyTrainOptions o = smallRun(96);
  o.searchEvery = 32;
  o.searchBudget = 20;
  PolicyTrainer trainer(o, toy, rollouts);
  ASSERT_TRUE(trainer.run(nullptr, {}));
  EXPECT_EQ(trainer.searchSummary().searches, 3);
  EXPECT_EQ(trainer.buffer().size(), 96 + 3 * 20);
  EXPECT_EQ(trainer.demonstrations().size(), 3);  // the toy has no invalid actions here
  EXPECT_GE(trainer.searchSummary().meanGain, 0.0);
  EXPECT_EQ(trainer.recentRewards(1000).size(), 96u);
  // Each demonstration is a point the toy scores as recorded, on some search passage.
  PolicyBatch s, a;
  Eigen::VectorXd q;
  trainer.demonstrations().exportEpisodes(s, a, q);
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    EXPECT_GT(q(i), -1.0);
    EXPECT_LE(a.row(i).cwiseAbs().maxCoeff(), 1.0);
  }
  // Without searches the same run has no demonstrations and a buffer of episodes only.
  o.searchEvery = 0;
  PolicyTrainer plain(o, toy, rollouts);
  ASSERT_TRUE(plain.run(nullptr, {}));
  EXPECT_EQ(plain.buffer().size(), 96);
  EXPECT_EQ(plain.demonstrations().size(), 0);
}

// wideNoiseShare: that share of the episodes explores with wideNoiseSigma. One batch (one
// actor snapshot) without schedule noise: an episode's action, and so its reward, differs
// from the noise-free run's exactly where it drew the wide noise; with share 0 nothing is
// drawn and wideNoiseSigma changes nothing.
TEST(PolicyTrainer, AShareOfTheEpisodesExploresWithTheWideNoise) {
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(1);
  PolicyTrainOptions o = smallRun(64);
  o.batchEpisodes = 64;
  o.noiseStartSigma = 0;
  o.noiseAmplitude = 0;
  auto rewardsOf = [&](double share, double sigma) {
    PolicyTrainOptions run = o;
    run.wideNoiseShare = share;
    run.wideNoiseSigma = sigma;
    PolicyTrainer trainer(run, toy, rollouts);
    EXPECT_TRUE(trainer.run(nullptr, {}));
    return trainer.recentRewards(64);
  };
  const std::vector<double> quiet = rewardsOf(0, 0.5), otherSigma = rewardsOf(0, 0.9);
  EXPECT_EQ(quiet, otherSigma);
  const std::vector<double> half = rewardsOf(0.5, 0.5), all = rewardsOf(1, 0.5);
  ASSERT_EQ(half.size(), 64u);
  int differ = 0, allDiffer = 0;
  for (std::size_t i = 0; i < 64; ++i) {
    differ += half[i] != quiet[i];
    allDiffer += all[i] != quiet[i];
  }
  EXPECT_EQ(allDiffer, 64);
  EXPECT_GE(differ, 16);  // binomial(64, 0.5): 32 +- 4
  EXPECT_LE(differ, 48);

  // With wideNoiseActions only the named actions are widened; the others keep the
  // schedule's sigma (0 here), so they are the noise-free run's actions exactly.
  auto actionsOf = [&](const std::vector<int>& widened) {
    PolicyTrainOptions run = o;
    run.wideNoiseShare = 1;
    run.wideNoiseActions = widened;
    PolicyTrainer trainer(run, toy, rollouts);
    EXPECT_TRUE(trainer.run(nullptr, {}));
    PolicyBatch s, a;
    Eigen::VectorXd q;
    trainer.buffer().exportEpisodes(s, a, q);
    return a;
  };
  PolicyTrainOptions noiseFree = o;
  PolicyTrainer still(noiseFree, toy, rollouts);
  ASSERT_TRUE(still.run(nullptr, {}));
  PolicyBatch s, quietActions;
  Eigen::VectorXd q;
  still.buffer().exportEpisodes(s, quietActions, q);
  const PolicyBatch one = actionsOf({1});
  ASSERT_EQ(one.rows(), 64);
  for (Eigen::Index k = 0; k < one.cols(); ++k) {
    const double change = (one.col(k) - quietActions.col(k)).cwiseAbs().maxCoeff();
    if (k == 1) EXPECT_GT(change, 0.1);
    else EXPECT_EQ(change, 0.0) << "action " << k;
  }
}

// -startFrom: another run's checkpoint (other seed, other settings) carries on under this
// run's settings; a plain resume of the same file is refused.
TEST(PolicyTrainer, StartingFromAnotherRunsCheckpointKeepsItsWeightsAndEpisodes) {
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(1);
  const auto file = testData::tempFolder("policyTrainerStartFrom") / "base.pt";
  PolicyTrainer base(smallRun(64), toy, rollouts);
  ASSERT_TRUE(base.run(nullptr, {}));
  base.saveCheckpoint(file);

  PolicyTrainOptions next = smallRun(128);
  next.seed = 5;
  next.searchEvery = 32;
  next.searchBudget = 10;
  next.imitationWeight = 0.5;
  EXPECT_NE(resumeError(next, file).find("seed 11"), std::string::npos);
  PolicyTrainer continued(next, toy, rollouts);
  continued.resume(file, false);
  EXPECT_EQ(continued.episode(), 64);
  EXPECT_EQ(fingerprint(continued.learner(), 24, 8), fingerprint(base.learner(), 24, 8));
  EXPECT_EQ(continued.recentRewards(1000), base.recentRewards(1000));
  ASSERT_TRUE(continued.run(nullptr, {}));
  EXPECT_EQ(continued.episode(), 128);
  EXPECT_EQ(continued.searchSummary().searches, 2);  // after episodes 96 and 128
}

// -startFrom may switch between the two validity critics (the same tensors, the quality
// read through a sigmoid or not): the actor carries over unchanged. A plain resume with the
// other model, and a start from the reward critic (other tensors), are refused.
TEST(PolicyTrainer, StartingFromAnotherRunMaySwitchTheQualityNetworkToBounded) {
  const ToyEnvironment toy(24, 8, 3, 0.05);
  ThreadRollouts rollouts(1);
  const auto dir = testData::tempFolder("policyTrainerStartBounded");
  PolicyTrainOptions unbounded = smallRun(64);
  unbounded.criticModel = CriticModel::validityAndQuality;
  PolicyTrainer base(unbounded, toy, rollouts);
  ASSERT_TRUE(base.run(nullptr, {}));
  base.saveCheckpoint(dir / "unbounded.pt");
  PolicyTrainOptions rewardOnly = smallRun(64);
  PolicyTrainer rewardBase(rewardOnly, toy, rollouts);
  ASSERT_TRUE(rewardBase.run(nullptr, {}));
  rewardBase.saveCheckpoint(dir / "reward.pt");

  PolicyTrainOptions bounded = smallRun(128);
  bounded.criticModel = CriticModel::validityAndBoundedQuality;
  EXPECT_NE(resumeError(bounded, dir / "unbounded.pt").find("validityAndQuality"), std::string::npos);
  PolicyTrainer continued(bounded, toy, rollouts);
  continued.resume(dir / "unbounded.pt", false);
  EXPECT_EQ(continued.episode(), 64);
  EXPECT_EQ(fingerprint(continued.learner(), 24, 8).first, fingerprint(base.learner(), 24, 8).first);
  const Eigen::VectorXd q = fingerprint(continued.learner(), 24, 8).second;
  EXPECT_NE(q, fingerprint(base.learner(), 24, 8).second);  // the quality is read through the sigmoid
  EXPECT_TRUE(q.allFinite());
  ASSERT_TRUE(continued.run(nullptr, {}));
  EXPECT_EQ(continued.episode(), 128);
  // And back: a bounded run's checkpoint continues under the unbounded critic.
  continued.saveCheckpoint(dir / "bounded.pt");
  PolicyTrainOptions back = smallRun(160);
  back.criticModel = CriticModel::validityAndQuality;
  PolicyTrainer unboundedAgain(back, toy, rollouts);
  unboundedAgain.resume(dir / "bounded.pt", false);
  EXPECT_EQ(unboundedAgain.episode(), 128);
  EXPECT_EQ(fingerprint(unboundedAgain.learner(), 24, 8).first, fingerprint(continued.learner(), 24, 8).first);

  PolicyTrainer fromReward(bounded, toy, rollouts);
  try {
    fromReward.resume(dir / "reward.pt", false);
    ADD_FAILURE() << "a reward critic's checkpoint was accepted by a validity critic";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the checkpoint's networks are"), std::string::npos) << e.what();
  }
}

// -actorFrom: a new run's actor starts as a trained policy's. An eight-action policy (the
// shipped ensemble's members) gives its eight actions, and the splits start at exactly 0;
// an ensemble, another network or another state scaling is refused with the file named.
TEST(PolicyTrainer, TheActorStartsAsATrainedPolicysWithTheSplitsItLacksAtZero) {
  const PassageEnvironment passages;
  const auto dir = testData::tempFolder("actorFrom");
  auto writePolicy = [&](const std::string& name, int actions, std::vector<int> hidden) {
    const ActorCritic learner(NetworkLayout{policyStateSize, actions, hidden, 0.01, CriticModel::reward},
                              LearningRates{}, 5);
    std::filesystem::create_directories(dir / name);
    writePolicyFiles(dir / name / "policy.xml", learner, passages.stateScaling(), PolicyProvenance{1, 0.5, "test"});
    return dir / name / "policy.xml";
  };
  const Policy eight = Policy::load(writePolicy("eight", MeshingParameters::methodSize, {16, 16}));
  ThreadRollouts rollouts(1);
  PolicyTrainer trainer(smallRun(32), passages, rollouts);
  trainer.startActorFrom(eight, passages.stateScaling());
  for (std::uint64_t i = 0; i < 3; ++i) {
    const EpisodeTask task = passages.draw(20261202, i, EpisodePurpose::validation);
    PolicyState s;
    std::copy(task.state.begin(), task.state.end(), s.begin());
    const PolicyAction expected = eight.act(s);
    const PolicyBatch got = trainer.learner().act(statesOf({task}, policyStateSize));
    for (int k = 0; k < MeshingParameters::methodSize; ++k) EXPECT_NEAR(got(0, k), expected[k], 1e-6) << k;
    EXPECT_EQ(got(0, 8), 0.0);
    EXPECT_EQ(got(0, 9), 0.0);
  }
  // Other hidden layers than the run's, another scaling: refused, the file named.
  const Policy wide = Policy::load(writePolicy("wide", policyActionSize, {32, 16}));
  try {
    trainer.startActorFrom(wide, passages.stateScaling());
    ADD_FAILURE() << "another layout was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("wide"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("layout"), std::string::npos) << e.what();
  }
  PolicyStateScaling other = passages.stateScaling();
  other.logarithmic.fill(false);
  EXPECT_THROW(trainer.startActorFrom(eight, other), InputError);
  std::ofstream(dir / "pair.xml") << "<policy><format>passageMesh policy ensemble 1</format>"
                                     "<members>eight/policy.xml eight/policy.xml</members></policy>\n";
  EXPECT_THROW(trainer.startActorFrom(Policy::load(dir / "pair.xml"), passages.stateScaling()), InputError);
}

// <actorUpdatesFrom>: before that episode only the critic learns; the actor is the start's.
TEST(PolicyTrainer, TheActorWaitsForItsFirstUpdateEpisode) {
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(1);
  PolicyTrainOptions o = smallRun(64);
  o.validationPassages = 0;
  PolicyTrainer straight(o, toy, rollouts);
  o.actorUpdatesFrom = 64;
  PolicyTrainer waiting(o, toy, rollouts), fresh(o, toy, rollouts);
  ASSERT_TRUE(straight.run(nullptr, {}));
  ASSERT_TRUE(waiting.run(nullptr, {}));
  EXPECT_EQ(fingerprint(waiting.learner(), 24, 8).first, fingerprint(fresh.learner(), 24, 8).first);
  EXPECT_NE(fingerprint(waiting.learner(), 24, 8).second, fingerprint(fresh.learner(), 24, 8).second);
  EXPECT_NE(fingerprint(straight.learner(), 24, 8).first, fingerprint(fresh.learner(), 24, 8).first);
}

// A checkpoint of the learner-beside-rollouts schedule holds a batch built but not yet
// learnt: a run of the paper's order started from it (-startFrom) learns it first and ends
// at its episodes; asking for fewer episodes than the checkpoint has built is refused.
TEST(PolicyTrainer, ABatchBuiltButNotLearntIsLearntFirstWhenStartedUnderTheOtherSchedule) {
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(1);
  PolicyTrainOptions during = smallRun(160);
  during.learnerSchedule = LearnerSchedule::duringNextRollouts;
  const auto file = testData::tempFolder("policyTrainerSchedules") / "checkpoint.pt";
  {
    PolicyTrainer first(during, toy, rollouts);
    ASSERT_TRUE(testRuns::runToFirstCheckpoint(first, file));
    ASSERT_EQ(first.episode(), 64);
    ASSERT_EQ(first.buffer().size(), 64);  // the batch of episodes 64-79 is built, not learnt
  }
  PolicyTrainer after(smallRun(160), toy, rollouts);
  after.resume(file, false);
  EXPECT_EQ(after.episode(), 64);
  ASSERT_TRUE(after.run(nullptr, {}));
  EXPECT_EQ(after.episode(), 160);
  EXPECT_EQ(after.buffer().size(), 160);

  PolicyTrainOptions fewer = during;
  fewer.episodes = 72;
  PolicyTrainer tooShort(fewer, toy, rollouts);
  try {
    tooShort.resume(file);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the checkpoint has built 80 episodes (64 learnt): ask for at least that many <episodes>, not 72"),
              std::string::npos) << e.what();
  }
}

// A tournament's trial (policyTrain to its <episodes>, then -resume with more): under
// duringNextRollouts the finished run builds the batch past its end while it learns its
// last one, as a longer run does, and keeps it in its checkpoint; so the continuation has
// the weights of one straight run. A -startFrom drops that batch (its run builds its first
// batch under its own settings); a finished run resumed at its own length runs nothing.
TEST(PolicyTrainer, AFinishedRunResumedToMoreEpisodesGivesTheWeightsOfOneStraightRun) {
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(1);
  PolicyTrainOptions longer = smallRun(160);  // the learner updates from episode 20
  longer.learnerSchedule = LearnerSchedule::duringNextRollouts;
  PolicyTrainOptions trial = longer;
  trial.episodes = 64;
  const auto file = testData::tempFolder("policyTrainerTrial") / "checkpoint.pt";
  {
    PolicyTrainer first(trial, toy, rollouts);
    ASSERT_TRUE(first.run(nullptr, {}));
    ASSERT_EQ(first.episode(), 64);
    first.saveCheckpoint(file);
  }
  PolicyTrainer straight(longer, toy, rollouts);
  ASSERT_TRUE(straight.run(nullptr, {}));

  PolicyTrainer again(trial, toy, rollouts);  // resumed at its own length: nothing to run
  again.resume(file);
  ASSERT_TRUE(again.run(nullptr, {}));
  EXPECT_EQ(again.episode(), 64);
  again.saveCheckpoint(file);  // still holds the batch past the end

  PolicyTrainer continued(longer, toy, rollouts);
  continued.resume(file);
  EXPECT_EQ(continued.episode(), 64);
  ASSERT_TRUE(continued.run(nullptr, {}));
  EXPECT_EQ(fingerprint(continued.learner(), 24, 8), fingerprint(straight.learner(), 24, 8));
  ASSERT_EQ(continued.validationCurve().size(), straight.validationCurve().size() + 1);  // + the trial's end
  EXPECT_EQ(continued.validationCurve().back().meanReward, straight.validationCurve().back().meanReward);

  PolicyTrainer restarted(longer, toy, rollouts);  // -startFrom: the batch past the end dropped
  restarted.resume(file, false);
  ASSERT_TRUE(restarted.run(nullptr, {}));
  EXPECT_EQ(restarted.episode(), 160);
  EXPECT_EQ(restarted.buffer().size(), 160);
  EXPECT_NE(fingerprint(restarted.learner(), 24, 8).first, fingerprint(straight.learner(), 24, 8).first);

  PolicyTrainOptions tooFew = longer;  // between the end and the batch built past it
  tooFew.episodes = 72;
  PolicyTrainer refused(tooFew, toy, rollouts);
  try {
    refused.resume(file);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the checkpoint has built 80 episodes (64 learnt)"), std::string::npos)
        << e.what();
  }
}

// <heldActions>: the held actions are the start action's in every episode (no noise) and
// in the trained actor for every state; the others explore and learn.
TEST(PolicyTrainer, HeldActionsKeepTheStartActionInEveryEpisodeAndState) {
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(1);
  PolicyTrainOptions o = smallRun(160);
  o.heldActions = {6, 7};
  PolicyTrainer trainer(o, toy, rollouts);
  const PolicyBatch startActions = trainer.learner().act(PolicyBatch::Zero(1, 24));
  ASSERT_TRUE(trainer.run(nullptr, {}));
  PolicyBatch s, a;
  Eigen::VectorXd r;
  trainer.buffer().exportEpisodes(s, a, r);
  ASSERT_EQ(a.rows(), 160);
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    EXPECT_EQ(a(i, 6), startActions(0, 6));
    EXPECT_EQ(a(i, 7), startActions(0, 7));
  }
  EXPECT_GT((a.col(0).array() - a(0, 0)).abs().maxCoeff(), 0.1);  // explored
  const PolicyBatch after = trainer.learner().act(s.topRows(20));
  for (Eigen::Index i = 0; i < after.rows(); ++i) EXPECT_EQ(after(i, 7), startActions(0, 7));
  EXPECT_NE(trainer.learner().act(PolicyBatch::Zero(1, 24))(0, 0), startActions(0, 0));  // learnt
}

// Learning rates far too large make the networks NaN within a few batches: the run stops
// with one line that says so, before it meshes NaN actions (it ended in "buildHohMesh: nT
// must be at least 8") and before another checkpoint.
TEST(PolicyTrainer, ADivergedLearnerStopsTheRunWithAClearError) {
  PolicyTrainOptions o = smallRun(256);
  o.learningRates = {1e12, 1e12};
  const ToyEnvironment toy(24, 8, 3);
  ThreadRollouts rollouts(1);
  PolicyTrainer diverging(o, toy, rollouts);
  try {
    diverging.run(nullptr, {});
    FAIL() << "a learner with learning rates of 1e12 did not diverge";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("the learner diverged by episode "), std::string::npos) << e.what();
  }
  // Nor is its state written as a checkpoint (one it would refuse to resume from).
  const auto file = testData::tempFolder("policyTrainerDiverged") / "checkpoint.pt";
  EXPECT_THROW(diverging.saveCheckpoint(file), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(file));
}
