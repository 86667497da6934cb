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

// Beyond the sizes the fit computes with, a clear error instead of an overflow (1e300: the
// fit crashed) or an underflow (1e-155: it returned another shape).
TEST(BladePoints, RefusesPointsOfNoComputableSize) {
  const auto loop = BladeShape(testData::typicalTurbineBlade()).sampleLoop(50);
  const auto message = [&](double scale) {
    std::vector<Eigen::Vector2d> scaled;
    for (const auto& p : loop) scaled.push_back(scale * p);
    try {
      orderBladePoints(setOf(scaled));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(1e300).find("test.dat:1: coordinate beyond +-1e+100"), std::string::npos) << message(1e300);
  EXPECT_NE(message(1e-155).find("test.dat: the points span"), std::string::npos) << message(1e-155);
  EXPECT_EQ(message(1e90), "accepted");
  EXPECT_EQ(message(1e-90), "accepted");
}
