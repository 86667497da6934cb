// The starting guess of bladeFit (guessBladeParameters): from the points alone it must
// place the blade (edges, chord, stagger) close enough for the search to start in the
// right basin; with given edge angles it must keep them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "BladeTestData.hpp"
#include "passageMesh/blade/BladeFit.hpp"
#include "passageMesh/blade/BladePoints.hpp"
#include "passageMesh/blade/BladeSampler.hpp"

using namespace passageMesh;

namespace {

std::vector<Eigen::Vector2d> orderedLoop(const BladeParameters& blade, int count) {
  PointSet input;
  input.file = "sampled";
  input.points = BladeShape(blade).sampleLoop(count);
  return orderBladePoints(input).points;
}

}  // namespace

TEST(BladeFitGuess, PlacesSampledBladesNearTheirTrueEdgesChordAndStagger) {
  // The guess starts from the points furthest apart and moves the edges to where the
  // profile is perpendicular to its estimated camber angles; on round edges (radiusLe up
  // to 0.32 in the sampler's box) its chord and edges are still off by up to a tenth of the
  // chord, which the search corrects; a grossly wrong start (edges swapped, a side lost)
  // would be off by far more.
  BladeSampler sampler(BladeParameterRange::readDefault(), 20261208);
  double worstChord = 0, worstStagger = 0, worstEdge = 0;
  for (int b = 0; b < 40; ++b) {
    const BladeParameters truth = sampler.next();
    const BladeParameters guess = guessBladeParameters(orderedLoop(truth, 400));
    worstChord = std::max(worstChord, std::abs(guess.chord / truth.chord - 1));
    worstStagger = std::max(worstStagger, std::abs(guess.stagger - truth.stagger));
    worstEdge = std::max(worstEdge, std::hypot(guess.xLe - truth.xLe, guess.yLe - truth.yLe) / truth.chord);
  }
  std::printf("worst of 40: chord %.4f relative, stagger %.3f deg, leading edge %.4f chord\n", worstChord,
              worstStagger, worstEdge);
  EXPECT_LT(worstChord, 0.12);
  EXPECT_LT(worstStagger, 12.0);
  EXPECT_LT(worstEdge, 0.2);

  // A blade with thin edges is placed almost exactly.
  const BladeParameters turbine = testData::typicalTurbineBlade();
  const BladeParameters guess = guessBladeParameters(orderedLoop(turbine, 400));
  EXPECT_NEAR(guess.chord, turbine.chord, 0.01 * turbine.chord);
  EXPECT_NEAR(guess.stagger, turbine.stagger, 1.0);
  EXPECT_LT(std::hypot(guess.xLe - turbine.xLe, guess.yLe - turbine.yLe), 0.02 * turbine.chord);
}

TEST(BladeFitGuess, KeepsTheEdgeAnglesItIsGiven) {
  const BladeParameters truth = testData::typicalTurbineBlade();
  const auto points = orderedLoop(truth, 400);
  for (const double shift : {-10.0, 0.0, 10.0}) {
    const BladeParameters guess = guessBladeParameters(points, truth.thetaLe + shift, truth.thetaTe - shift);
    EXPECT_EQ(guess.thetaLe, truth.thetaLe + shift);
    EXPECT_EQ(guess.thetaTe, truth.thetaTe - shift);
    EXPECT_NEAR(guess.chord, truth.chord, 0.05 * truth.chord);
  }
}
