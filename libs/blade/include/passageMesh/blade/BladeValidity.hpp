#pragma once
// Checks that a blade shape is one the mesher can use (docs/blade-parametrization.md):
// positive chord and edge radii, no negative thickness, a camber line single-valued in x,
// sides that do not cross (a simple closed profile), and exactly two extreme points of x
// along the profile (one leading-edge minimum, one trailing-edge maximum), so that each
// side seen from the passage is a graph over x.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "passageMesh/blade/BladeShape.hpp"

namespace passageMesh {

struct BladeValidity {
  bool valid = true;
  std::string reason;  // empty when valid
  explicit operator bool() const { return valid; }
};

BladeValidity checkBladeValidity(const BladeShape& shape);

// True when the closed polygon `loop` (no repeated closing point) has two non-adjacent
// edges that intersect or touch. O(n log n) in practice (edges sorted by x).
bool closedPolygonSelfIntersects(const std::vector<Eigen::Vector2d>& loop,
                                 int* firstEdge = nullptr, int* secondEdge = nullptr);

}  // namespace passageMesh
