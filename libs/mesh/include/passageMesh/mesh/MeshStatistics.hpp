#pragma once
// What ellipticMesh reports about a mesh, and what the tests hold it to (issue 3): the wall
// layer of the O-block against the requested first cell height and orthogonality, and the
// uniformity of the H-blocks (blockNonUniformity, in libs/structured).
#include <Eigen/Core>

#include "passageMesh/structured/BlockUniformity.hpp"  // blockNonUniformity
#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

// The wall normal the statistics measure against at a wall node: the chord from its
// neighbour before to its neighbour after, turned by +90 degrees (outward for nodes
// clockwise around the blade). buildHohMesh holds the first row within
// HohMeshOptions::wallAngleLimit of it.
inline Eigen::Vector2d discreteWallNormal(const Eigen::Vector2d& before, const Eigen::Vector2d& after) {
  const Eigen::Vector2d tangent = (after - before).normalized();
  return {-tangent.y(), tangent.x()};
}

struct WallLayerStatistics {
  // First cell height: the distance of node (i, 1) from the wall along the wall normal
  // (normal to the chord from wall node i - 1 to i + 1), relative to the requested one.
  double heightWithin2Percent = 0;   // fraction of wall nodes with |h / dn1 - 1| <= 0.02
  double heightMaxError = 0;         // largest |h / dn1 - 1|
  int heightWorstNode = 0;           // its i
  // Wall-line angle: between that wall chord and the first j-line segment, in degrees.
  double angleMeanDeviation = 0;     // mean |angle - 90|
  double angleMaxDeviation = 0;
  int angleWorstNode = 0;
};

// `oBlock`: i around the blade with the seam repeated (ni = nT + 1), j = 0 on the wall.
WallLayerStatistics wallLayerStatistics(const StructuredBlock& oBlock, double firstCellHeight);

}  // namespace passageMesh
