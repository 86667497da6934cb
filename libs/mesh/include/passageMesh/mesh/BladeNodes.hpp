#pragma once
// The O-block's wall nodes (method.md section 4): nT distinct nodes around the blade,
// split between the sides in proportion to their lengths, each side's nodes placed by
// arc length with tanhStretch (gammaLE towards the leading edge, gammaTE towards the
// trailing edge).
//
// Order: clockwise, from the trailing-edge point along the lower side to the
// leading-edge point and back along the upper side, so that i around the blade and j
// away from it form a right-handed (positive Jacobian) index system. The O-block repeats
// node 0 at i = nT to close the loop.
#include <Eigen/Core>
#include <vector>

#include "passageMesh/blade/BladeShape.hpp"

namespace passageMesh {

struct BladeNode {
  BladeSide side = BladeSide::lower;
  double u = 0;                  // side parameter (0 leading, 1 trailing edge)
  Eigen::Vector2d point;         // [m]
  Eigen::Vector2d outwardNormal;
};

std::vector<BladeNode> distributeBladeNodes(const BladeShape& blade, int nT, double gammaLe,
                                            double gammaTe);

}  // namespace passageMesh
