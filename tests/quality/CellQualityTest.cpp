// The quality of hand-computed cells: the unit square, a 60-degree rhombus, a trapezoid,
// and a rectangle next to one of twice its area (method.md section 5).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "QualityTestData.hpp"
#include "passageMesh/quality/MeshQuality.hpp"
#include "passageMesh/quality/NodeJacobians.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;

TEST(CellQuality, UnitSquareIsPerfect) {
  const MeshQuality q = computeMeshQuality(singleCell({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}));
  EXPECT_TRUE(q.valid) << q.problem;
  EXPECT_DOUBLE_EQ(q.QJmin, 1);
  EXPECT_DOUBLE_EQ(q.QSmin, 1);
  EXPECT_DOUBLE_EQ(q.Q, 1);
  EXPECT_EQ(q.worstQS.i, 0);
  EXPECT_DOUBLE_EQ(q.worstQS.x, 0.5);
  EXPECT_DOUBLE_EQ(q.worstQS.y, 0.5);
}

TEST(CellQuality, RhombusWithSixtyDegreesHasTwoThirds) {
  const double h = std::sqrt(3.0) / 2;
  const MeshQuality q = computeMeshQuality(singleCell({{{0, 0}, {1, 0}, {1.5, h}, {0.5, h}}}));
  ASSERT_TRUE(q.valid) << q.problem;
  // Angles 60 and 120 degrees: 1 - max(30, 30) / 90. A parallelogram: J equal everywhere.
  EXPECT_NEAR(q.QSmin, 2.0 / 3, 1e-15);
  EXPECT_NEAR(q.QJmin, 1, 1e-15);
  EXPECT_NEAR(q.Q, (1 + 1 + 2.0 / 3 + 2.0 / 3) / 4, 1e-15);
}

TEST(CellQuality, Trapezoid) {
  // Base 2, top 1, height 1: angles atan(2) at the base, 180 - atan(2) at the top.
  const MeshQuality q = computeMeshQuality(singleCell({{{0, 0}, {2, 0}, {1.5, 1}, {0.5, 1}}}));
  ASSERT_TRUE(q.valid) << q.problem;
  const double baseAngle = std::atan(2.0) * 180 / std::numbers::pi;
  EXPECT_NEAR(q.QSmin, 1 - (90 - baseAngle) / 90, 1e-14);
  // Two nodes per direction: first-order differences. Bottom nodes: x_xi = (2, 0),
  // x_eta = (+-0.5, 1), J = 2; top nodes: x_xi = (1, 0), J = 1.
  EXPECT_NEAR(q.QJmin, 0.5, 1e-15);
}

TEST(CellQuality, RectangleNextToOneOfTwiceItsArea) {
  // Columns at x = -1, 0, 1, 3, 5: cell (1, 1) is 0..1, cell (2, 1) is 1..3 (twice the
  // area), both with interior corner nodes. J = x_xi * y_eta with y_eta = 1:
  // x_xi = 1 at x = 0, 1.5 at x = 1, 2 at x = 3.
  StructuredMesh mesh;
  mesh.blocks = {tensorBlock("OBlock", {-1, 0, 1, 3, 5}, {-1, 0, 1, 2})};
  const MeshQuality q = computeMeshQuality(mesh, {.everyBlock = true});
  ASSERT_TRUE(q.valid) << q.problem;
  const auto& qJ = q.cellQJ[0];
  const int cellsPerRow = 4;
  EXPECT_NEAR(qJ[1 + cellsPerRow * 1], 1 / 1.5, 1e-15);
  EXPECT_NEAR(qJ[2 + cellsPerRow * 1], 1.5 / 2, 1e-15);
  for (double qS : q.cellQS[0]) EXPECT_NEAR(qS, 1, 1e-15);  // rectangles
  EXPECT_NEAR(q.QSmin, 1, 1e-15);
}

TEST(CellQuality, InvertedCellMakesTheMeshInvalid) {
  // Clockwise corners: negative area.
  const MeshQuality q = computeMeshQuality(singleCell({{{0, 0}, {0, 1}, {1, 1}, {1, 0}}}));
  EXPECT_FALSE(q.valid);
  EXPECT_EQ(q.Q, invalidMeshQuality);
  EXPECT_NE(q.problem.find("OBlock cell (0, 0)"), std::string::npos) << q.problem;
  // A bow tie (two corners swapped).
  const MeshQuality bowTie = computeMeshQuality(singleCell({{{0, 0}, {1, 0}, {0, 1}, {1, 1}}}));
  EXPECT_FALSE(bowTie.valid);
  EXPECT_EQ(bowTie.Q, invalidMeshQuality);
}

// The node Jacobians behind Q_J: on an affine block (x = 2i + j, y = 3j) every difference,
// central inside and one-sided on the edges, gives the exact J = 6; mirrored, -6.
TEST(NodeJacobians, AnAffineBlockHasItsJacobianAtEveryNodeEdgesIncluded) {
  StructuredBlock b;
  b.ni = 5;
  b.nj = 4;
  for (int j = 0; j < b.nj; ++j)
    for (int i = 0; i < b.ni; ++i) {
      b.x.push_back(2.0 * i + j);
      b.y.push_back(3.0 * j);
    }
  std::vector<double> jacobian(static_cast<std::size_t>(b.ni * b.nj));
  nodeJacobians(b, false, nullptr, jacobian.data());
  for (std::size_t k = 0; k < jacobian.size(); ++k) EXPECT_NEAR(jacobian[k], 6, 1e-12) << "node " << k;
  for (double& y : b.y) y = -y;
  nodeJacobians(b, false, nullptr, jacobian.data());
  for (std::size_t k = 0; k < jacobian.size(); ++k) EXPECT_NEAR(jacobian[k], -6, 1e-12) << "node " << k;
}
