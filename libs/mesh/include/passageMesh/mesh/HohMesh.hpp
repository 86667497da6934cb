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
// The O-block is built on few rows first: j-lines leave each wall node along the
// (smoothed) wall normal and end at the facing outer-loop node (cubic Hermite curves),
// HohMeshOptions::smoothingRows rows evenly spaced along each; smoothOBlock
// (EllipticSmoother.hpp) solves the elliptic grid equations on them with lines
// orthogonal at the wall and at the outer loop; then the nN final rows are placed along
// the smoothed lines, clustered so that the first one sits exactly firstCellHeight from
// the wall (LineRedistribution.hpp); where those rows fold, they are placed again with a
// longer wall blend. Where that mesh is invalid, it is built again without the outer
// loop's orthogonality control, then without the wall's (HohMeshOptions,
// docs/elliptic-smoothing.md "Second try" and "Tries without the wall's orthogonality");
// where every try is invalid, the outer loop is moved away from a blade it runs close to,
// then the node clustering toward the defaults' (HohMeshOptions::outerLoopRoom,
// clusteringMoves).
#include <string>

#include "passageMesh/mesh/EllipticSmoother.hpp"

#include "passageMesh/blade/BladeShape.hpp"
#include "passageMesh/structured/CellValidity.hpp"  // findInvalidCell
#include "passageMesh/structured/StructuredMesh.hpp"
#include "passageMesh/passage/MeshingParameters.hpp"
#include "passageMesh/passage/PassageCondition.hpp"

namespace passageMesh {

struct HohMeshOptions {
  bool smooth = true;          // false: the algebraic mesh only
  // The elliptic equations are solved on this many rows (at most nN), evenly spaced along
  // the lines; the final nN rows are then placed along the smoothed lines
  // (LineRedistribution.hpp; docs/elliptic-smoothing.md has the measurements).
  int smoothingRows = 33;
  // Over this many wall node spacings from the wall (at least 20 firstCellHeight) the final
  // nodes blend from the wall normal into the smoothed line (LineRedistribution.hpp).
  double wallBlendLength = 3.0;
  // The wall lines leave the wall within this many degrees of its normal (the normal to
  // the chord between a wall node's neighbours, as MeshStatistics measures it): where the
  // smoothed wall normals turn further (next to an edge sharper than the node spacing),
  // they are turned back to this angle (below the 10 degrees a wall-resolved RANS grid
  // asks for; docs/elliptic-smoothing.md). 0: no limit.
  double wallAngleLimit = 9.5;
  // Where the O-block folds after the rows are placed, they are placed again with the
  // blend twice as long, at most this many times (0: never; docs/elliptic-smoothing.md
  // "Longer wall blend where the rows fold").
  int wallBlendRetries = 3;
  // Where the mesh is invalid, it is built again with less asked of the smoothing and the
  // first valid try is kept (HohMesh::retryWithout says which). This one allows the try
  // without elliptic.outerOrthogonality (and, with the next, the one without both) ...
  bool secondTryWithoutOuterOrthogonality = true;
  // ... and this one the try without elliptic.wallOrthogonality (tried after the first).
  bool triesWithoutWallOrthogonality = true;
  // Where every try is invalid, the mesh is built again with moved meshing parameters,
  // each move on top of the one before, and the first valid one is kept
  // (HohMesh::parametersMoved says what moved and why); a mesh valid with the parameters
  // asked for is never changed, and a passage cut by a periodic boundary (no passage
  // exists) is not moved. First, where the blade comes within this many chords of the
  // O-block's outer loop, the loop is moved away: yIn, yOut, alphaCamber toward the
  // defaults', betaIn, betaOut toward their upper bound, the smallest common fraction of
  // the way that leaves this much room (all the way when that loop leaves less, but more
  // than the loop asked for; no move when it leaves no more). 0: never.
  double outerLoopRoom = 0.1;
  // Then gammaLE and gammaTE halfway to the defaults', then to them: the wall nodes
  // clustered enough at the edges for their curvature.
  bool clusteringMoves = true;
  // Then (on top of the defaults' clustering where that was tried) splitIn and splitOut
  // halfway to the defaults', then to them: the method's outer loop.
  bool splitMoves = true;
  EllipticOptions elliptic;

  // These options with every parameter move above off: the mesh of the parameters as
  // asked, or invalid (the tries without orthogonality stay).
  HohMeshOptions withoutParameterMoves() const {
    HohMeshOptions asked = *this;
    asked.outerLoopRoom = 0;
    asked.clusteringMoves = false;
    asked.splitMoves = false;
    return asked;
  }
};

struct HohMesh {
  StructuredMesh mesh;
  int nN = 0;                  // O-block nodes normal to the wall
  bool valid = false;          // every cell of every block has positive area, convex corners
  std::string problem;         // why not valid (empty when valid)
  EllipticReport smoothing;    // sweeps, final residual, converged (sweeps 0: not smoothed)
  // The meshing parameters the mesh was built with: those asked for, unless moved
  // (parametersMoved).
  MeshingParameters parameters;
  // Non-empty when the parameters were moved to mesh the passage (HohMeshOptions::
  // outerLoopRoom, clusteringMoves, splitMoves): each one changed, old -> new, and why.
  std::string parametersMoved;
  // Non-empty when the mesh is a later try (HohMeshOptions) or its parameters were moved:
  // why the first, with the parameters asked for and every orthogonality control, was
  // invalid ...
  std::string firstTryProblem;
  // ... and where the kept try drops the orthogonality: "the outer loop", "the wall" or
  // "the wall and the outer loop".
  std::string retryWithout;
  // The wall blend the rows were placed with, in wall node spacings: longer than
  // HohMeshOptions::wallBlendLength when the rows folded with it (0: not placed).
  double wallBlendLength = 0;
};

// Throws std::invalid_argument only for arguments no mesh can have (nT < 8);
// a geometry that gives a folded or degenerate mesh returns valid = false with the reason.
HohMesh buildHohMesh(const BladeShape& blade, const PassageCondition& condition,
                     const MeshingParameters& parameters, const HohMeshOptions& options = {});

}  // namespace passageMesh
