#include "passageMesh/policy/PolicyScaling.hpp"

#include <gtest/gtest.h>

#include <random>

#include "../blade/BladeTestData.hpp"
#include "passageMesh/passage/PassageSampler.hpp"

using namespace passageMesh;

TEST(PolicyScaling, SampledPassagesAreInsideTheUnitBoxAndMovingOrScalingChangesNothing) {
  for (const PassageDraw& d : samplePassages(20, 5)) {
    const PolicyState s = policyState(d.blade, d.condition);
    for (double v : s) {
      EXPECT_GE(v, -1.0);
      EXPECT_LE(v, 1.0);
    }
    EXPECT_TRUE(stateOutsideTraining(s).empty());
    // Q does not change when the passage is moved or scaled, so neither may the state.
    BladeParameters moved = d.blade;
    PassageCondition scaled = d.condition;
    moved.xLe += 0.03;
    moved.yLe -= 0.02;
    moved.chord *= 1.7;
    scaled.pitch *= 1.7;
    scaled.xIn *= 1.7;
    scaled.xOut *= 1.7;
    scaled.firstCellHeight *= 1.7;
    const PolicyState t = policyState(moved, scaled);
    for (int k = 0; k < policyStateSize; ++k) EXPECT_NEAR(t[k], s[k], 1e-12) << policyStateNames()[k];
  }
}

TEST(PolicyScaling, ConditionEdgesMapToPlusMinusOneAndOutsideValuesAreNamed) {
  const BladeParameters blade = testData::typicalTurbineBlade();
  PassageCondition c{0.3 * blade.chord, 0.0, 1.0 * blade.chord, 50000, 2e-5 * blade.chord};
  const PolicyState s = policyState(blade, c);
  EXPECT_NEAR(s[19], -1.0, 1e-12);  // pitch
  EXPECT_NEAR(s[20], -1.0, 1e-12);  // xIn
  EXPECT_NEAR(s[21], 1.0, 1e-12);   // xOut
  EXPECT_NEAR(s[22], 1.0, 1e-12);   // nO
  EXPECT_NEAR(s[23], -1.0, 1e-12);  // firstCellHeight
  c.pitch = 1.5 * blade.chord;
  const auto lines = stateOutsideTraining(policyState(blade, c));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("pitch"), std::string::npos) << lines[0];
}

TEST(PolicyScaling, ActionsRoundTripAndAreClippedToTheParameterBox) {
  const double chord = 0.07;
  const MeshingParameters p = MeshingParameters::defaults(chord);
  const MeshingParameters back = meshingParametersOf(policyAction(p, chord), chord);
  const auto a = p.toArray(), b = back.toArray();
  for (int k = 0; k < MeshingParameters::size; ++k) EXPECT_NEAR(a[k], b[k], 1e-12 * std::max(1.0, std::abs(a[k])));

  PolicyAction wild{};
  wild.fill(3.0);
  wild[0] = -7.0;
  const auto clipped = meshingParametersOf(wild, chord).toArray();
  const auto lo = MeshingParameters::lowerBounds(chord), hi = MeshingParameters::upperBounds(chord);
  EXPECT_DOUBLE_EQ(clipped[0], lo[0]);
  for (int k = 1; k < MeshingParameters::size; ++k) EXPECT_DOUBLE_EQ(clipped[k], hi[k]);
  PolicyAction middle{};
  EXPECT_EQ(meshingParametersOf(middle, chord).nT, 550);  // the middle of [100, 1000]
}
