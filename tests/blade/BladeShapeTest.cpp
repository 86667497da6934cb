#include "passageMesh/blade/BladeShape.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "BladeTestData.hpp"
#include "passageMesh/blade/BladeProjection.hpp"
#include "passageMesh/core/PointFile.hpp"

using namespace passageMesh;

TEST(BladeShape, SidesMeetAtTheEdgesPerpendicularToTheCamberLine) {
  const BladeShape shape(testData::typicalTurbineBlade());
  for (BladeSide side : {BladeSide::lower, BladeSide::upper}) {
    EXPECT_LT((shape.point(side, 0.0) - shape.leadingEdge()).norm(), 1e-15);
    EXPECT_LT((shape.point(side, 1.0) - shape.trailingEdge()).norm(), 1e-15);
    for (double u : {0.0, 1.0}) {
      const Eigen::Vector2d t = shape.derivative(side, u).normalized();
      const Eigen::Vector2d camber = shape.camberDerivative(u).normalized();
      EXPECT_NEAR(t.dot(camber), 0.0, 1e-12);
    }
  }
}

TEST(BladeShape, EdgeCurvatureEqualsTheEdgeRadius) {
  const BladeParameters p = testData::typicalTurbineBlade();
  const BladeShape shape(p);
  for (BladeSide side : {BladeSide::lower, BladeSide::upper}) {
    EXPECT_NEAR(shape.curvature(side, 0.0), 1.0 / (p.radiusLe * p.chord), 1e-8 / p.chord);
    EXPECT_NEAR(shape.curvature(side, 1.0), 1.0 / (p.radiusTe * p.chord), 1e-7 / p.chord);
  }
}

TEST(BladeShape, LoopIsCounterClockwiseWithOutwardNormals) {
  const BladeShape shape(testData::typicalTurbineBlade());
  const auto loop = shape.sampleLoop(2000);
  ASSERT_EQ(loop.size(), 2000u);
  double area2 = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const auto& a = loop[k];
    const auto& b = loop[(k + 1) % loop.size()];
    area2 += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_GT(area2, 0.0);
  // A point just outside along the outward normal projects back with positive distance.
  BladeProjector projector(shape);
  for (BladeSide side : {BladeSide::lower, BladeSide::upper})
    for (double u : {0.1, 0.5, 0.9}) {
      const Eigen::Vector2d q = shape.point(side, u) + 1e-3 * shape.outwardNormal(side, u);
      const FootPoint foot = projector.project(q);
      EXPECT_EQ(foot.side, side);
      EXPECT_NEAR(foot.u, u, 1e-9);
      EXPECT_NEAR(foot.signedDistance, 1e-3, 1e-12);
    }
}

TEST(BladeShape, ScalingTheChordScalesTheProfile) {
  BladeParameters p = testData::typicalTurbineBlade();
  const BladeShape a(p);
  p.chord *= 3.0;
  p.xLe *= 3.0;
  p.yLe *= 3.0;
  const BladeShape b(p);
  for (double u : {0.0, 0.3, 0.8})
    EXPECT_LT((3.0 * a.point(BladeSide::upper, u) - b.point(BladeSide::upper, u)).norm(), 1e-14);
}

// method.md section 2: ParaBlade's own matched parameters, built as ParaBlade builds them,
// sit on the tutorial points with these mean/max deviations [m].
namespace {
Deviation paraBladeDeviation(const std::string& blade, const testData::ParaBladeSection& s) {
  // The tutorial copies hold the same points as shared/blades (and ship with the project).
  const auto points = readPointFile(testData::tutorialPoints(blade)).points;
  return testData::deviationFromPolyline(points, testData::paraBladeProfile(s, 20000));
}
}  // namespace

TEST(BladeShape, ReproducesParaBladeReferenceProfileForSIRT) {
  const Deviation d = paraBladeDeviation("SIRT", testData::paraBladeSIRT());
  EXPECT_NEAR(d.mean, 1.25e-4, 0.03e-4);
  EXPECT_NEAR(d.max, 3.57e-4, 0.03e-4);
}

TEST(BladeShape, ReproducesParaBladeReferenceProfileForLS89) {
  const Deviation d = paraBladeDeviation("LS89", testData::paraBladeLS89());
  EXPECT_NEAR(d.mean, 7.3e-5, 0.3e-5);
  EXPECT_NEAR(d.max, 3.2e-4, 0.1e-4);
}
