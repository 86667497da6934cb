#include "passageMesh/policy/PolicyEnvironment.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "passageMesh/quality/MeshQuality.hpp"

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
