// The LibTorch networks and the learner: gradients against finite differences, and
// learning a problem with a known optimum.
#include "passageMesh/policy/ActorCritic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <random>

#include "passageMesh/policy/PolicyNetworks.hpp"
#include "passageMesh/policy/PolicyTrainer.hpp"
#include "passageMesh/policy/ToyEnvironment.hpp"

using namespace passageMesh;

TEST(ActorCritic, CriticGradientsMatchFiniteDifferences) {
  torch::manual_seed(4);
  NetworkLayout layout{3, 2, {5, 4}, 0.01};
  FullyConnected critic = makeCritic(layout);
  critic->to(torch::kFloat64);
  const torch::Tensor input = torch::rand({6, 5}, torch::kFloat64) * 2 - 1;
  const torch::Tensor target = torch::rand({6, 1}, torch::kFloat64);
  auto loss = [&] { return torch::mse_loss(critic->forward(input), target); };
  critic->zero_grad();
  loss().backward();
  torch::NoGradGuard noGrad;
  const double h = 1e-6;
  int checked = 0;
  for (auto& p : critic->parameters()) {
    const torch::Tensor flat = p.view(-1);
    const torch::Tensor grad = p.grad().view(-1);
    for (long i = 0; i < flat.size(0); ++i) {
      const double v = flat[i].item<double>();
      flat[i] = v + h;
      const double up = loss().item<double>();
      flat[i] = v - h;
      const double down = loss().item<double>();
      flat[i] = v;
      EXPECT_NEAR(grad[i].item<double>(), (up - down) / (2 * h), 1e-7);
      ++checked;
    }
  }
  EXPECT_EQ(checked, (5 * 5 + 5) + (5 * 4 + 4) + (4 + 1));
}

TEST(ActorCritic, ActorOutputsStayInsideTheActionBox) {
  ActorCritic learner(NetworkLayout{4, 3, {8}, 0.01}, LearningRates{}, 1);
  PolicyBatch states = PolicyBatch::Constant(5, 4, 1e3);
  const PolicyBatch a = learner.act(states);
  EXPECT_EQ(a.rows(), 5);
  EXPECT_EQ(a.cols(), 3);
  EXPECT_LE(a.cwiseAbs().maxCoeff(), 1.0);
}

// A critic that rewards ever larger actions (r = mean of a) drives a plain actor's tanh into
// saturation, where its gradient vanishes; the bound penalty keeps it off the flat end.
TEST(ActorCritic, TheBoundPenaltyKeepsTheActorOffTheFlatEndsOfTanh) {
  auto largestAction = [](double penalty) {
    ActorCritic learner(NetworkLayout{3, 2, {16, 16}, 0.01}, LearningRates{1e-2, 1e-2}, 3);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> uniform(-1, 1);
    PolicyBatch s(64, 3), a(64, 2);
    Eigen::VectorXd r(64);
    for (int step = 0; step < 400; ++step) {
      for (int k = 0; k < 64; ++k) {
        for (int c = 0; c < 3; ++c) s(k, c) = uniform(rng);
        for (int c = 0; c < 2; ++c) a(k, c) = uniform(rng);
        r(k) = a.row(k).mean();
      }
      learner.updateCritic(s, a, r);
      learner.updateActor(s, penalty);
    }
    return learner.act(s).cwiseAbs().maxCoeff();
  };
  const double plain = largestAction(0), penalised = largestAction(10);
  std::printf("largest action magnitude: plain %.5f, penalised %.5f\n", plain, penalised);
  EXPECT_GT(plain, 0.99);
  EXPECT_LT(penalised, 0.975);
  EXPECT_GT(penalised, 0.9);  // it still goes where the critic points, up to the edge
}

// The must-show of issue 12: the actor-critic learns x*(c) of a problem with the passage's
// state and action sizes to an RMS error below 0.05 on unseen conditions. Small networks,
// actor 3e-4 and critic 1e-3 learning rates; 40000 episodes, about 40 s on one core
// (docs/benchmarks.md "Policy learner").
TEST(ActorCritic, LearnsAToyProblemsOptimalActions) {
  PolicyTrainOptions options;
  options.episodes = 40000;
  options.hidden = {64, 64};
  options.learningRates = {3e-4, 1e-3};
  options.validationPassages = 0;
  options.threads = 1;
  const ToyEnvironment toy(24, 8, 7);
  ThreadRollouts rollouts(1);
  PolicyTrainer trainer(options, toy, rollouts);
  const double before = toy.actionError(trainer.learner(), 99, 1000);
  ASSERT_TRUE(trainer.run(nullptr, {}));
  const double after = toy.actionError(trainer.learner(), 99, 1000);
  EXPECT_GT(before, 0.3);
  EXPECT_LT(after, 0.05) << "RMS action error on unseen states, started at " << before;
}

// The optimum's first entry lies 0.05 below a region of failures (reward -1). A critic
// split into validity and quality learns it as closely as the plain critic learns the toy
// without failures, with the actor climbing the expected reward or q + 0.1 log p; the
// plain critic, whose squared error mixes the -1 into the quality fit, stays about 0.1
// away (bench/policyLearnerBenchmark, docs/policy.md).
TEST(ActorCritic, TheValidityAndQualityCriticLearnsAnOptimumBesideFailures) {
  for (const double barrier : {0.0, 0.1}) {
    SCOPED_TRACE("validityBarrier " + std::to_string(barrier));
    PolicyTrainOptions options;
    options.episodes = 40000;
    options.hidden = {64, 64};
    options.learningRates = {3e-4, 1e-3};
    options.noiseStartSigma = 0.3;  // the shipped policy's exploration
    options.noiseAmplitude = 0.1;
    options.criticModel = CriticModel::validityAndQuality;
    options.validityBarrier = barrier;
    options.validationPassages = 0;
    options.threads = 1;
    const ToyEnvironment toy(24, 8, 7, 0.05);
    ThreadRollouts rollouts(1);
    PolicyTrainer trainer(options, toy, rollouts);
    ASSERT_TRUE(trainer.run(nullptr, {}));
    const double after = toy.actionError(trainer.learner(), 99, 1000);
    EXPECT_LT(after, 0.05) << "RMS action error on unseen states";
    const std::vector<double> rewards = trainer.buffer().recentRewards(1000);
    EXPECT_GT(std::count(rewards.begin(), rewards.end(), -1.0), 50) << "exploration met too few failures";
  }
}

// The imitation term pulls the actor to demonstrated actions: with it alone dominant, pi(s)
// reaches the demonstrations; with weight 0 it has no effect.
TEST(ActorCritic, ImitationPullsTheActorToTheDemonstratedActions) {
  NetworkLayout layout{3, 2, {16, 16}, 0.01};
  PolicyBatch s(4, 3), target(4, 2);
  s << -0.5, 0.2, 0.9, 0.1, -0.8, 0.3, 0.7, 0.7, -0.2, 0.0, 0.5, -0.6;
  target << 0.6, -0.4, -0.7, 0.2, 0.3, 0.8, -0.1, -0.9;
  ActorCritic pulled(layout, {1e-2, 1e-3}, 3), untouched(layout, {1e-2, 1e-3}, 3);
  const PolicyBatch before = pulled.act(s);
  for (int step = 0; step < 400; ++step) {
    pulled.updateActor(s, 0, 0, Imitation{s, target, 10.0});
    untouched.updateActor(s, 0, 0, Imitation{s, target, 0.0});
  }
  EXPECT_GT((before - target).cwiseAbs().maxCoeff(), 0.3);
  EXPECT_LT((pulled.act(s) - target).cwiseAbs().maxCoeff(), 0.05);
  EXPECT_GT((untouched.act(s) - target).cwiseAbs().maxCoeff(), 0.3);

  // Demonstrations on the bounds pull to 0.95 of the half-range, not into tanh's flat end.
  PolicyBatch onBounds(4, 2);
  onBounds << 1, -1, -1, 1, 1, 1, -1, -1;
  ActorCritic bounded(layout, {1e-2, 1e-3}, 3);
  for (int step = 0; step < 600; ++step) bounded.updateActor(s, 0, 0, Imitation{s, onBounds, 10.0});
  EXPECT_LT((bounded.act(s) - 0.95 * onBounds).cwiseAbs().maxCoeff(), 0.01);
}

// An actor that trains only some outputs keeps the others (and its hidden layers, on which
// they depend) bit for bit, while the trained ones still reach their targets.
TEST(ActorCritic, AnActorTrainingSomeOutputsOnlyKeepsTheOthersBitForBit) {
  NetworkLayout layout{3, 2, {16, 16}, 0.01};
  PolicyBatch s(4, 3), target(4, 2);
  s << -0.5, 0.2, 0.9, 0.1, -0.8, 0.3, 0.7, 0.7, -0.2, 0.0, 0.5, -0.6;
  target << 0.6, -0.4, -0.7, 0.2, 0.3, 0.8, -0.1, -0.9;
  ActorCritic learner(layout, {1e-2, 1e-3}, 3);
  learner.trainActorOutputsOnly({1});
  const PolicyBatch before = learner.act(s);
  for (int step = 0; step < 3000; ++step) learner.updateActor(s, 0, 0, Imitation{s, target, 10.0});
  const PolicyBatch after = learner.act(s);
  EXPECT_GT((before.col(1) - target.col(1)).cwiseAbs().maxCoeff(), 0.3);
  EXPECT_LT((after.col(1) - target.col(1)).cwiseAbs().maxCoeff(), 0.05);
  for (Eigen::Index i = 0; i < s.rows(); ++i) EXPECT_EQ(after(i, 0), before(i, 0));
  // The same steps with every output training move output 0 too.
  ActorCritic free(layout, {1e-2, 1e-3}, 3);
  for (int step = 0; step < 600; ++step) free.updateActor(s, 0, 0, Imitation{s, target, 10.0});
  EXPECT_GT((free.act(s).col(0) - before.col(0)).cwiseAbs().maxCoeff(), 0.3);
  EXPECT_THROW(learner.trainActorOutputsOnly({2}), std::invalid_argument);
}

// Held outputs are their start value for every state, before and after training, while the
// others and the hidden layers learn (the splits held at 0 for a policy of eight actions).
TEST(ActorCritic, HeldActorOutputsStayAtTheirStartForEveryState) {
  NetworkLayout layout{3, 3, {16, 16}, 0.01};
  PolicyBatch s(4, 3), target(4, 3);
  s << -0.5, 0.2, 0.9, 0.1, -0.8, 0.3, 0.7, 0.7, -0.2, 0.0, 0.5, -0.6;
  target << 0.6, -0.4, 0.5, -0.7, 0.2, -0.5, 0.3, 0.8, 0.4, -0.1, -0.9, -0.3;
  ActorCritic learner(layout, {1e-2, 1e-3}, 3, {0.1, -0.2, 0.25});
  learner.holdActorOutputs({2});
  const PolicyBatch before = learner.act(s);
  for (Eigen::Index i = 0; i < s.rows(); ++i) EXPECT_NEAR(before(i, 2), 0.25, 1e-7);  // (float weights)
  for (int step = 0; step < 1500; ++step) learner.updateActor(s, 0, 0, Imitation{s, target, 10.0});
  const PolicyBatch after = learner.act(s);
  EXPECT_LT((after.leftCols(2) - target.leftCols(2)).cwiseAbs().maxCoeff(), 0.05);  // the others learn
  for (Eigen::Index i = 0; i < s.rows(); ++i) EXPECT_EQ(after(i, 2), before(0, 2));
  PolicyBatch far = 30.0 * s;  // any state, however far from the data
  EXPECT_EQ(learner.act(far).col(2), PolicyBatch::Constant(4, 1, before(0, 2)));
  EXPECT_THROW(learner.holdActorOutputs({3}), std::invalid_argument);
}

// validityAndBoundedQuality: the quality q = sigmoid(output) fits valid meshes' Q as the
// unbounded one does, but no input, however far from the data, makes the expected reward
// leave [-1, 1] (an unbounded q, fitted on the valid meshes only, extrapolates freely).
TEST(ActorCritic, TheBoundedQualityFitsValidMeshesAndStaysInItsRangeFarFromTheData) {
  const NetworkLayout layout{3, 2, {16, 16}, 0.01, CriticModel::validityAndBoundedQuality};
  ActorCritic critic(layout, {1e-3, 3e-3}, 5);
  PolicyBatch s(6, 3), a(6, 2);
  s << -0.5, 0.2, 0.9, 0.1, -0.8, 0.3, 0.7, 0.7, -0.2, 0.0, 0.5, -0.6, 0.4, 0.4, 0.4, -0.9, 0.1, 0.2;
  a << 0.6, -0.4, -0.7, 0.2, 0.3, 0.8, -0.1, -0.9, 0.5, 0.5, -0.3, 0.0;
  Eigen::VectorXd q(6);
  q << 0.9, 0.3, 0.65, 0.8, 0.5, 0.95;
  for (int step = 0; step < 3000; ++step) critic.updateCritic(s, a, q);
  EXPECT_LT((critic.value(s, a) - q).cwiseAbs().maxCoeff(), 0.02);
  for (const double far : {10.0, 100.0, 1e4}) {
    const Eigen::VectorXd v = critic.value(far * s, -far * a);
    EXPECT_LE(v.maxCoeff(), 1.0) << far;
    EXPECT_GE(v.minCoeff(), -1.0) << far;
  }
}

// A learner whose critic has diverged (here a NaN reward, one Adam step) is refused when its
// state is loaded (a checkpoint's networks, or the best validation's learner kept in it),
// naming the network and the weight: a run resumed from it would only mesh NaN actions.
TEST(ActorCritic, LoadingADivergedLearnerIsRefusedNamingTheWeight) {
  const NetworkLayout layout{3, 2, {8}, 0.01};
  ActorCritic sound(layout, LearningRates{}, 1), diverged(layout, LearningRates{}, 1);
  const PolicyBatch s = PolicyBatch::Constant(2, 3, 0.1), a = PolicyBatch::Constant(2, 2, 0.2);
  diverged.updateCritic(s, a, Eigen::VectorXd::Constant(2, std::numeric_limits<double>::quiet_NaN()));
  ActorCritic target(layout, LearningRates{}, 2);
  EXPECT_NO_THROW(target.loadStateBytes(sound.stateBytes()));
  try {
    target.loadStateBytes(diverged.stateBytes());
    FAIL() << "a critic with NaN weights was loaded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("the critic's layers.0.weight holds NaN or infinity"), std::string::npos)
        << e.what();
  }
}
