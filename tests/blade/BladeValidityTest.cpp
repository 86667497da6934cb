#include "passageMesh/blade/BladeValidity.hpp"

#include <gtest/gtest.h>

#include "BladeTestData.hpp"

using namespace passageMesh;

TEST(BladeValidity, TypicalBladeIsValid) {
  const BladeValidity v = checkBladeValidity(BladeShape(testData::typicalTurbineBlade()));
  EXPECT_TRUE(v.valid) << v.reason;
}

TEST(BladeValidity, NegativeThicknessIsInvalid) {
  BladeParameters p = testData::typicalTurbineBlade();
  p.thicknessLower[2] = -0.05;
  const BladeValidity v = checkBladeValidity(BladeShape(p));
  EXPECT_FALSE(v.valid);
  EXPECT_NE(v.reason.find("negative thickness"), std::string::npos) << v.reason;
}

TEST(BladeValidity, CamberTurningBackInXIsInvalid) {
  BladeParameters p = testData::typicalTurbineBlade();
  p.thetaTe = -120;  // the camber line ends running upstream
  const BladeValidity v = checkBladeValidity(BladeShape(p));
  EXPECT_FALSE(v.valid);
  EXPECT_NE(v.reason.find("single-valued"), std::string::npos) << v.reason;
}

TEST(BladeValidity, CrossingSidesAreInvalid) {
  BladeParameters p = testData::typicalTurbineBlade();
  // A thick lower side on a strongly cambered line folds over the upper side.
  p.thetaLe = 60;
  p.thetaTe = -80;
  p.distLe = p.distTe = 0.6;
  p.thicknessLower = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
  const BladeValidity v = checkBladeValidity(BladeShape(p));
  EXPECT_FALSE(v.valid);
  EXPECT_TRUE(v.reason.find("cross") != std::string::npos ||
              v.reason.find("extreme") != std::string::npos)
      << v.reason;
}

TEST(BladeValidity, MoreThanTwoExtremePointsIsInvalid) {
  BladeParameters p = testData::typicalTurbineBlade();
  // An S-shaped camber line (rising against a falling chord, then turning back up)
  // gives a lower side that runs back upstream and forward again.
  p.thetaLe = -26.8;
  p.thetaTe = 58.2;
  p.radiusLe = 0.030;
  p.distLe = 0.78;
  p.distTe = 0.41;
  const BladeValidity v = checkBladeValidity(BladeShape(p));
  EXPECT_FALSE(v.valid);
  EXPECT_NE(v.reason.find("4 extreme points"), std::string::npos) << v.reason;
}

TEST(BladeValidity, PolygonSelfIntersection) {
  const std::vector<Eigen::Vector2d> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Eigen::Vector2d> bowtie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  EXPECT_FALSE(closedPolygonSelfIntersects(square));
  int a = -1, b = -1;
  EXPECT_TRUE(closedPolygonSelfIntersects(bowtie, &a, &b));
  EXPECT_EQ(a, 0);
  EXPECT_EQ(b, 2);
}
