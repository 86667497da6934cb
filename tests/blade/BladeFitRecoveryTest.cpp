// Recovery: blades drawn by the sampler, turned into 200-400 points (half with noise of
// 1e-5 chord, every start point moved, half in reversed order), fitted: at least 95 %
// must come back within 1e-4 chord of the true shape (two-sided maximum distance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "passageMesh/blade/BladeFit.hpp"
#include "passageMesh/blade/BladePoints.hpp"
#include "passageMesh/blade/BladeProjection.hpp"
#include "passageMesh/blade/BladeSampler.hpp"
#include "passageMesh/core/InputError.hpp"

using namespace passageMesh;

namespace {

// Largest distance between two profiles, measured both ways on dense samplings.
double twoSidedDistance(const BladeShape& a, const BladeShape& b) {
  const Deviation ab = deviationFromProfile(b, a.sampleLoop(1500));
  const Deviation ba = deviationFromProfile(a, b.sampleLoop(1500));
  return std::max(ab.max, ba.max);
}

double gaussian(std::mt19937_64& rng) {  // Box-Muller on our own uniform variates
  const double u1 = 1.0 - uniform01(rng), u2 = uniform01(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2 * M_PI * u2);
}

}  // namespace

TEST(BladeFitRecovery, SampledBladesAreRecoveredFromNoisyShuffledPoints) {
  const int blades = 200;
  BladeSampler sampler(BladeParameterRange::readDefault(), 20261122);
  std::mt19937_64 rng(7);
  int recovered = 0, redrawn = 0;
  double worst = 0;
  for (int b = 0; b < blades; ++b) {
    const BladeParameters truth = sampler.next();
    const BladeShape trueShape(truth);
    const int count = 200 + static_cast<int>(uniform01(rng) * 201);
    const auto exact = trueShape.sampleLoop(count);
    const long shift = static_cast<long>(uniform01(rng) * count);
    // Noise can make the loop cross itself at a sharp edge, where the sides are closer
    // than the noise; a measured blade would not, so such a draw is redrawn.
    OrderedBladePoints ordered;
    for (int draw = 0;; ++draw) {
      auto loop = exact;
      if (b % 2 == 0)
        for (auto& p : loop)
          p += 1e-5 * truth.chord * Eigen::Vector2d(gaussian(rng), gaussian(rng));
      std::rotate(loop.begin(), loop.begin() + shift, loop.end());
      if (b % 4 < 2) std::reverse(loop.begin(), loop.end());
      PointSet input;
      input.file = "blade" + std::to_string(b);
      input.points = loop;
      try {
        ordered = orderBladePoints(input);
        break;
      } catch (const InputError&) {
        ASSERT_LT(draw, 20) << "blade " << b << ": no noise draw without a crossing";
        ++redrawn;
      }
    }
    const BladeFitResult fit = fitBlade(ordered.points);
    const double error = twoSidedDistance(trueShape, BladeShape(fit.parameters)) / truth.chord;
    worst = std::max(worst, error);
    if (error <= 1e-4) {
      ++recovered;
    } else {
      std::printf("blade %d: %d points, distance %.3e chord, fit mean %.3e max %.3e chord\n", b,
                  count, error, fit.meanDeviation / truth.chord, fit.maxDeviation / truth.chord);
    }
  }
  std::printf("recovered %d of %d within 1e-4 chord (worst %.3e chord; %d noise draws redrawn)\n",
              recovered, blades, worst, redrawn);
  EXPECT_GE(recovered, (95 * blades + 99) / 100);
}
