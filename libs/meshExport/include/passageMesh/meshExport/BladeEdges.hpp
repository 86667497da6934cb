#pragma once
// Where the blade's edges are, read from the mesh alone (exportMesh and plotMesh need no
// blade parameters): the trailing edge is the O-block's first wall node (its i runs from
// the trailing edge, HohMesh.hpp), the leading edge its most upstream wall node (least x:
// the flow runs towards +x; the node farthest from the trailing edge lies on the suction
// side of a highly cambered blade), and the chord their distance.
#include <Eigen/Core>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

struct BladeEdges {
  Eigen::Vector2d leadingEdge = Eigen::Vector2d::Zero(), trailingEdge = Eigen::Vector2d::Zero();
  double chord = 0;  // [m]
};

// Throws std::invalid_argument when the mesh has no block named "OBlock".
BladeEdges findBladeEdges(const StructuredMesh& mesh);

}  // namespace passageMesh
