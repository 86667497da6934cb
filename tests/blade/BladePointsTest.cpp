#include "passageMesh/blade/BladePoints.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "BladeTestData.hpp"
#include "passageMesh/core/InputError.hpp"

using namespace passageMesh;

namespace {
PointSet setOf(std::vector<Eigen::Vector2d> points) {
  PointSet s;
  s.file = "test.dat";
  s.points = std::move(points);
  return s;
}
}  // namespace

TEST(BladePoints, OrientationHoldsFarFromTheOriginAndAtAnyScale) {
  const auto loop = BladeShape(testData::typicalTurbineBlade()).sampleLoop(200);
  // (scale, offset) pairs that keep the points distinct in double precision.
  const double cases[][2] = {{1e-8, 0}, {1, 0}, {1e8, 0}, {1, 1e5}, {1e8, 1e8}};
  for (const auto& [scale, offset] : cases) {
    std::vector<Eigen::Vector2d> moved;
    for (const auto& p : loop) moved.push_back(scale * p + Eigen::Vector2d(offset, offset));
    EXPECT_FALSE(orderBladePoints(setOf(moved)).reversed) << scale << " " << offset;
    std::reverse(moved.begin(), moved.end());
    EXPECT_TRUE(orderBladePoints(setOf(moved)).reversed) << scale << " " << offset;
  }
}

TEST(BladePoints, DropsTheClosingRepeatAndKeepsInputIndices) {
  auto loop = BladeShape(testData::typicalTurbineBlade()).sampleLoop(50);
  std::reverse(loop.begin(), loop.end());
  loop.push_back(loop.front());
  const OrderedBladePoints ordered = orderBladePoints(setOf(loop));
  EXPECT_TRUE(ordered.closed);
  EXPECT_TRUE(ordered.reversed);
  ASSERT_EQ(ordered.points.size(), 50u);
  for (std::size_t k = 0; k < 50; ++k)
    EXPECT_EQ(ordered.points[k], loop[static_cast<std::size_t>(ordered.inputIndex[k])]);
}

TEST(BladePoints, RefusesCollinearPoints) {
  std::vector<Eigen::Vector2d> line;
  for (int k = 0; k < 30; ++k) line.emplace_back(k, 2.0 * k);
  EXPECT_THROW(orderBladePoints(setOf(line)), InputError);
}
