#pragma once
// The multi-block passage mesh as one unstructured 2-D mesh, the form the exporters for
// unstructured solvers (OpenFOAM, SU2) write: nodes merged across every non-periodic
// block connection (O/H interfaces, the O-block seam), so those become internal edges,
// and boundary edges grouped into the five named patches.
//
// Numbering: points in the order their first node appears (block by block, i fastest);
// cells block by block, i fastest, cell (i, j) with corners (i, j), (i + 1, j),
// (i + 1, j + 1), (i, j + 1): counterclockwise for the right-handed blocks of a valid mesh.
// Every edge runs p0 -> p1 counterclockwise around its owner cell, so the owner lies to its
// left and its outward normal (p1 - p0 turned clockwise) points away from the owner.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

struct MeshEdge {
  int p0 = 0, p1 = 0;
  int owner = 0;
  int neighbour = -1;  // -1 on a boundary
};

enum class EdgePatchKind { wall, inlet, outlet, periodicLower, periodicUpper };

struct EdgePatch {
  std::string name;
  EdgePatchKind kind = EdgePatchKind::wall;
  std::vector<MeshEdge> edges;
};

struct UnstructuredPassage {
  std::vector<Eigen::Vector2d> points;
  std::vector<std::array<int, 4>> cells;
  // Ordered by owner, then neighbour (owner < neighbour): OpenFOAM's upper-triangular order.
  std::vector<MeshEdge> internalEdges;
  // The mesh's wall, inlet and outlet patches (by name, in the mesh's order), then
  // "periodicLower" and "periodicUpper": edge k of the lower one plus `translation` is
  // edge k of the upper one.
  std::vector<EdgePatch> patches;
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();  // lower -> upper [m]
};

// Throws std::invalid_argument when the mesh is not a closed passage of this form: a
// range off a block edge, connected ranges of different lengths, periodic connections with
// different translations, a cell collapsed by the merging, an edge shared by more than two
// cells, or a boundary edge on no patch (or a patch on an internal edge).
UnstructuredPassage makeUnstructuredPassage(const StructuredMesh& mesh);

}  // namespace passageMesh
