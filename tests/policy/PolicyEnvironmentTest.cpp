#include "passageMesh/policy/PolicyEnvironment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "passageMesh/quality/MeshQuality.hpp"
#include "passageMesh/workflow/MeshQualityObjective.hpp"

using namespace passageMesh;

// TrainingMeshes: with asAsked a training episode whose mesh as asked is invalid scores -1
// where policyMesh's mesher moves the parameters and meshes; validation draws mesh as
// policyMesh either way. Validation passage 6 with betaIn at its lower bound: valid only
// after the mesher moves betaIn and betaOut (the blade comes within the outer loop's room).
TEST(PassageEnvironment, AsAskedTrainingMeshesScoreMinusOneWherePolicyMeshMovesTheParameters) {
  const PassageEnvironment product;
  const PassageEnvironment asAsked(EdgeRadiusDraw::halfLogUniform, product.stateScaling(), TrainingMeshes::asAsked);
  std::vector<double> action = product.defaultAction();
  action[3] = -1.0;  // betaIn
  const double moved = product.draw(20261202, 6, EpisodePurpose::training).reward(action);
  EXPECT_GT(moved, 0.0);
  EXPECT_EQ(product.draw(20261202, 6, EpisodePurpose::validation).reward(action), moved);
  EXPECT_EQ(asAsked.draw(20261202, 6, EpisodePurpose::validation).reward(action), moved);
  EXPECT_EQ(asAsked.draw(20261202, 6, EpisodePurpose::training).reward(action), invalidMeshQuality);
  // A mesh valid as asked scores the same in both.
  const std::vector<double> defaults = product.defaultAction();
  EXPECT_EQ(asAsked.draw(20261202, 6, EpisodePurpose::training).reward(defaults),
            product.draw(20261202, 6, EpisodePurpose::training).reward(defaults));
}

// passage() is the blade and condition draw() meshes: the same state, and an action's
// reward is the quality of that case's mesh at the action's meshing parameters.
TEST(PassageEnvironment, APassageIsTheBladeAndConditionItsEpisodeDraws) {
  const PassageEnvironment environment;
  for (const std::uint64_t episode : {0, 3, 17}) {
    const EpisodeTask task = environment.draw(20261202, episode, EpisodePurpose::validation);
    const PassageCase passage = environment.passage(20261202, episode);
    const PolicyState state = policyState(passage.blade.parameters(), passage.condition, environment.stateScaling());
    EXPECT_EQ(task.state, std::vector<double>(state.begin(), state.end())) << episode;
    const std::vector<double> defaults = environment.defaultAction();
    PolicyAction action{};
    std::copy(defaults.begin(), defaults.end(), action.begin());
    EXPECT_EQ(task.reward(defaults),
              meshQualityOf(passage, meshingParametersOf(action, passage.blade.parameters().chord)))
        << episode;
  }
  // Another episode is another passage.
  EXPECT_NE(environment.passage(20261202, 0).condition.pitch, environment.passage(20261202, 1).condition.pitch);
}

// The summary behind every validation curve and the choice of the best policy: invalid
// meshes (-1) count in the mean and the median, and not as valid.
TEST(RewardSummary, MeanMedianAndValidCountIncludeInvalidMeshes) {
  const RewardSummary s = summarizeRewards({-1, 0.2, 0.4, -1});
  EXPECT_DOUBLE_EQ(s.mean, -0.35);
  EXPECT_DOUBLE_EQ(s.median, -0.4);  // the mean of the middle two, -1 and 0.2
  EXPECT_EQ(s.valid, 2);
  EXPECT_EQ(s.count, 4);
  const RewardSummary odd = summarizeRewards({0.7, -1, 0.5});
  EXPECT_DOUBLE_EQ(odd.median, 0.5);
  EXPECT_EQ(odd.valid, 2);
  const RewardSummary none = summarizeRewards({});
  EXPECT_EQ(none.count, 0);
  EXPECT_EQ(none.mean, 0);
  EXPECT_EQ(none.median, 0);
}

// Each episode's random stream is its own: the same (seed, episode, stream) gives the same
// numbers, another of the three gives others; the normal variates have mean 0, variance 1.
TEST(EpisodeRandom, StreamsAreReproducibleAndIndependentAndNormalsAreStandard) {
  auto a = episodeRandom(7, 11, 2), b = episodeRandom(7, 11, 2);
  EXPECT_EQ(a(), b());
  EXPECT_NE(episodeRandom(7, 11, 2)(), episodeRandom(7, 12, 2)());
  EXPECT_NE(episodeRandom(7, 11, 2)(), episodeRandom(7, 11, 3)());
  EXPECT_NE(episodeRandom(7, 11, 2)(), episodeRandom(8, 11, 2)());
  auto rng = episodeRandom(1, 0, 0);
  double sum = 0, squares = 0;
  constexpr int n = 200000;
  for (int k = 0; k < n; ++k) {
    const double z = standardNormal(rng);
    ASSERT_TRUE(std::isfinite(z));
    sum += z;
    squares += z * z;
  }
  EXPECT_NEAR(sum / n, 0, 0.01);            // 4.5 standard errors
  EXPECT_NEAR(squares / n, 1, 0.015);       // about 4.7 standard errors
}
