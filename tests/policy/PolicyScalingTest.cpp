#include "passageMesh/policy/PolicyScaling.hpp"

#include <gtest/gtest.h>

#include <cmath>
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

TEST(PolicyScaling, EdgeRadiiScaleLogarithmicallyAndFormatOneScalesLinearly) {
  const BladeParameterRange range = BladeParameterRange::readDefault();
  const PolicyStateScaling logScale = policyStateScaling(range);
  const PolicyStateScaling linear = policyStateScaling(range, EdgeRadiusScale::linear);
  BladeParameters blade = testData::typicalTurbineBlade();
  const PassageCondition c{0.7 * blade.chord, 0.5 * blade.chord, 0.5 * blade.chord, 20000, 1e-4 * blade.chord};
  const int le = BladeParameters::radiusLeIndex - 3, te = BladeParameters::radiusTeIndex - 3;
  ASSERT_EQ(policyStateNames()[le], "radiusLe");
  ASSERT_EQ(policyStateNames()[te], "radiusTe");
  for (int k = 0; k < policyStateSize; ++k) {
    EXPECT_EQ(logScale.logarithmic[k], k == le || k == te) << policyStateNames()[k];
    EXPECT_FALSE(linear.logarithmic[k]);
  }
  blade.radiusLe = range.lower[BladeParameters::radiusLeIndex];
  blade.radiusTe = std::sqrt(range.lower[BladeParameters::radiusTeIndex] * range.upper[BladeParameters::radiusTeIndex]);
  PolicyState s = policyState(blade, c, logScale);
  EXPECT_NEAR(s[le], -1.0, 1e-12);
  EXPECT_NEAR(s[te], 0.0, 1e-12);  // the geometric mean is the middle of a log scale
  // A sharp edge (STD10's 1e-4 chord) and one three times blunter lie far apart on the log
  // scale (0.37 units) and close together on the linear one (0.03).
  blade.radiusTe = 1e-4;
  const double sharpLog = policyState(blade, c, logScale)[te], sharpLinear = policyState(blade, c, linear)[te];
  blade.radiusTe = 3e-4;
  EXPECT_GT(policyState(blade, c, logScale)[te] - sharpLog, 0.3);
  EXPECT_LT(policyState(blade, c, linear)[te] - sharpLinear, 0.05);
  // The other entries do not depend on the edge-radius scale.
  s = policyState(blade, c, logScale);
  const PolicyState t = policyState(blade, c, linear);
  for (int k = 0; k < policyStateSize; ++k)
    if (k != le && k != te) {
      EXPECT_EQ(s[k], t[k]) << policyStateNames()[k];
    }
  // A radius of 0 stays finite and is named as outside the training range.
  blade.radiusTe = 0;
  s = policyState(blade, c, logScale);
  EXPECT_TRUE(std::isfinite(s[te]));
  const auto lines = stateOutsideTraining(s);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("radiusTe"), std::string::npos) << lines[0];
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

TEST(PolicyScaling, ANonFiniteActionIsRefusedNamingTheParameter) {
  PolicyAction action{};
  action[5] = std::nan("");
  try {
    meshingParametersOf(action, 0.1);
    FAIL() << "a NaN action was turned into meshing parameters";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the policy's action for nT is not a number"), std::string::npos) << e.what();
  }
}
