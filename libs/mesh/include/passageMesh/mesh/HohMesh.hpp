#pragma once
// The HOH passage mesh (method.md section 4) built in-process: an H-block from the inlet
// to the inlet interface, the O-block around the blade, an H-block from the outlet
// interface to the outlet. No disk I/O: the optimisers and the trainer call this.
//
// Blocks (StructuredMesh::blocks): 0 "HInlet", 1 "OBlock", 2 "HOutlet".
//   H-blocks: i along +x, j along +y (lower to upper periodic boundary), uniform cells.
//   OBlock: i clockwise around the blade from the trailing edge (nT + 1 nodes, the seam
//   node repeated: i = 0 and i = nT coincide), j from the wall (0) outwards (nN nodes).
// Both index systems are right-handed: every valid cell has positive area.
//
// This version places the O-block nodes algebraically: j-lines leave each wall node along
// the wall normal and end at the facing outer-loop node (cubic Hermite curves), with the
// nodes along each line clustered to the wall so that the first one sits exactly
// firstCellHeight away. Elliptic smoothing follows in a later version (issue 3).
#include <string>

#include "passageMesh/blade/BladeShape.hpp"
#include "passageMesh/mesh/StructuredMesh.hpp"
#include "passageMesh/passage/MeshingParameters.hpp"
#include "passageMesh/passage/PassageCondition.hpp"

namespace passageMesh {

struct HohMesh {
  StructuredMesh mesh;
  int nN = 0;            // O-block nodes normal to the wall
  bool valid = false;    // every cell of every block has positive area, convex corners
  std::string problem;   // why not valid (empty when valid)
};

// Throws std::invalid_argument only for arguments no mesh can have (nT < 8, nO < 2 nT);
// a geometry that gives a folded or degenerate mesh returns valid = false with the reason.
HohMesh buildHohMesh(const BladeShape& blade, const PassageCondition& condition,
                     const MeshingParameters& parameters);

// The first cell (block, i, j) with non-positive area or a non-convex corner, as text;
// empty when there is none.
std::string findInvalidCell(const StructuredMesh& mesh);

}  // namespace passageMesh
