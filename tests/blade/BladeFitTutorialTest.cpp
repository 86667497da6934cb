// bladeFit on the four tutorial blades: the input points must lie no further from our
// fitted profile than from ParaBlade's reference fits (shared/blades/README.md), in metres,
// and the fitted parameters must lie in the sampler's range box.
#include <gtest/gtest.h>

#include "BladeTestData.hpp"
#include "passageMesh/blade/BladeFit.hpp"
#include "passageMesh/blade/BladePoints.hpp"
#include "passageMesh/blade/BladeSampler.hpp"

using namespace passageMesh;

namespace {

struct Reference {
  const char* blade;
  double mean, max;  // ParaBlade's fit deviations [m]
};

// T106A: ParaBlade's 1e-6 / 5e-6 m in its unscaled frame, times the x99.4885 scale.
const Reference references[] = {{"LS89", 4.0e-5, 2.43e-4},
                                {"STD10", 1.1e-5, 5.8e-5},
                                {"T106A", 1e-6 * 99.4885, 5e-6 * 99.4885},
                                {"SIRT", 1.27e-4, 3.57e-4}};

void PrintTo(const Reference& r, std::ostream* os) { *os << r.blade; }

class TutorialFit : public ::testing::TestWithParam<Reference> {};

}  // namespace

TEST_P(TutorialFit, DeviationsNoLargerThanParaBlade) {
  const Reference& ref = GetParam();
  const auto ordered = orderBladePoints(readPointFile(testData::tutorialPoints(ref.blade)));
  const BladeFitResult fit = fitBlade(ordered.points);
  std::printf("%s: mean %.3e m (ParaBlade %.3e), max %.3e m (ParaBlade %.3e), %.2f s\n",
              ref.blade, fit.meanDeviation, ref.mean, fit.maxDeviation, ref.max, fit.seconds);
  EXPECT_TRUE(fit.validity.valid) << fit.validity.reason;
  EXPECT_LE(fit.meanDeviation, ref.mean);
  EXPECT_LE(fit.maxDeviation, ref.max);
  // The sampler's box must hold every tutorial blade (method.md section 2).
  EXPECT_TRUE(BladeParameterRange::readDefault().contains(fit.parameters));
}

INSTANTIATE_TEST_SUITE_P(Tutorials, TutorialFit, ::testing::ValuesIn(references),
                         [](const auto& testInfo) { return std::string(testInfo.param.blade); });
