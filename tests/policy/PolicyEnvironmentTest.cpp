#include "passageMesh/policy/PolicyEnvironment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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
