#include <gtest/gtest.h>

#include "passageMesh/optimize/MeshingParameterSpace.hpp"

using namespace passageMesh;

TEST(MeshingParameterSpace, IsTheMethodRangeBoxWithIntegerNt) {
  const BoxProblem box = meshingParameterProblem(0.2);
  box.check();
  ASSERT_EQ(box.dimension(), 10);
  EXPECT_DOUBLE_EQ(box.lower[0], -0.1);
  EXPECT_DOUBLE_EQ(box.upper[1], 0.1);
  EXPECT_EQ(box.lower[5], 100);
  EXPECT_EQ(box.upper[5], 1000);
  for (int k = 0; k < 10; ++k) EXPECT_EQ(box.isInteger(k), k == 5) << k;
  EXPECT_EQ(box.name(5), "nT");
  EXPECT_EQ(box.name(6), "gammaLE");
  EXPECT_EQ(box.name(8), "splitIn");
  EXPECT_DOUBLE_EQ(box.lower[9], -0.5);  // splitOut, in pitches whatever the chord
  EXPECT_DOUBLE_EQ(box.upper[9], 0.5);
}

TEST(MeshingParameterSpace, RoundTripsAndRoundsNt) {
  MeshingParameters p = MeshingParameters::defaults(0.2);
  p.yIn = 0.031;
  p.nT = 512;
  const Eigen::VectorXd v = toOptimizerVector(p);
  EXPECT_EQ(v[5], 512);
  EXPECT_EQ(toMeshingParameters(v).toArray(), p.toArray());
  Eigen::VectorXd w = v;
  w[5] = 512.6;
  EXPECT_EQ(toMeshingParameters(w).nT, 513);
  const BoxProblem box = meshingParameterProblem(0.2);
  w[5] = 1000.4;
  w[0] = -1;
  const Eigen::VectorXd e = box.evaluatedPoint(w);
  EXPECT_EQ(e[5], 1000);
  EXPECT_DOUBLE_EQ(e[0], -0.1);
  EXPECT_THROW(toMeshingParameters(Eigen::VectorXd::Zero(7)), std::invalid_argument);
}
