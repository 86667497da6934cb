#include "passageMesh/mesh/BladeNodes.hpp"

#include <gtest/gtest.h>

#include "../blade/BladeTestData.hpp"
#include "passageMesh/blade/BladeProjection.hpp"

using namespace passageMesh;

namespace {
double signedArea(const std::vector<BladeNode>& nodes) {
  double a2 = 0;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const auto& p = nodes[k].point;
    const auto& q = nodes[(k + 1) % nodes.size()].point;
    a2 += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a2;
}
}  // namespace

TEST(BladeNodes, ClockwiseFromTheTrailingEdgeOnTheProfile) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const auto nodes = distributeBladeNodes(blade, 300, 1.0, 2.0);
  ASSERT_EQ(nodes.size(), 300u);
  EXPECT_LT(signedArea(nodes), 0.0);  // clockwise
  EXPECT_LT((nodes[0].point - blade.trailingEdge()).norm(), 1e-15);
  int leadingEdge = -1;
  for (std::size_t k = 0; k < nodes.size(); ++k)
    if ((nodes[k].point - blade.leadingEdge()).norm() < 1e-15) leadingEdge = static_cast<int>(k);
  EXPECT_GT(leadingEdge, 100);
  EXPECT_LT(leadingEdge, 200);
  for (const auto& n : nodes) {
    EXPECT_LT(std::abs(deviationFromProfile(blade, {n.point}).max), 1e-12);
    EXPECT_NEAR(n.outwardNormal.norm(), 1.0, 1e-14);
  }
}

TEST(BladeNodes, ClusteringShrinksTheSpacingAtItsOwnEdge) {
  const BladeShape blade(testData::typicalTurbineBlade());
  auto teSpacing = [&](double gLe, double gTe) {
    const auto n = distributeBladeNodes(blade, 300, gLe, gTe);
    return (n[1].point - n[0].point).norm();
  };
  const auto uniform = distributeBladeNodes(blade, 300, 0, 0);
  // Uniform in arc length: neighbouring spacings on one side agree to the arc-length table.
  const double d1 = (uniform[11].point - uniform[10].point).norm();
  const double d2 = (uniform[51].point - uniform[50].point).norm();
  EXPECT_NEAR(d1, d2, 0.02 * d1);
  EXPECT_LT(teSpacing(1, 4), 0.2 * teSpacing(1, 0));
  EXPECT_NEAR(teSpacing(3, 2), teSpacing(0, 2), 0.01 * teSpacing(0, 2));
}
