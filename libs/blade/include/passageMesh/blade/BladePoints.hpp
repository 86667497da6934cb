#pragma once
// Scattered blade points as a user gives them (any start point, either orientation, open
// or closed, any scale or position), checked and put in a standard order: a closed loop
// without repeated closing point, counter-clockwise in (x, y).
#include <Eigen/Core>
#include <vector>

#include "passageMesh/core/PointFile.hpp"

namespace passageMesh {

inline constexpr int minimumBladePoints = 20;
// The sizes the fit computes with: its points' span in x or y and the largest |x| or |y|
// (LS89's points scaled by 1e300 overflowed in the fit, by 1e-155 they underflowed, while
// 1e-150 to 1e150 gave its shape: these bounds lie well inside, and far from any blade).
inline constexpr double minimumBladeSize = 1e-100, maximumBladeSize = 1e100, maximumBladeCoordinate = 1e100;

struct OrderedBladePoints {
  std::vector<Eigen::Vector2d> points;  // counter-clockwise loop
  std::vector<int> inputIndex;          // index of each point in the input
  bool reversed = false;                // the input ran clockwise
  bool closed = false;                  // the input repeated its first point at the end
};

// Throws InputError naming the file (and line) for: fewer than minimumBladePoints
// distinct points, a coordinate beyond maximumBladeCoordinate, a span outside
// [minimumBladeSize, maximumBladeSize], duplicate points, a self-intersecting loop, a
// zero-area loop.
OrderedBladePoints orderBladePoints(const PointSet& input);

}  // namespace passageMesh
