#pragma once
// The a-priori mesh quality Q of method.md section 5, computed in-process without disk
// I/O (optimisers and the trainer call it for every mesh they try). docs/quality.md has
// the formulas and the neighbour rules.
//
// Over the cells of the O-block (block "OBlock"):
//   Q = (min Q_J + mean Q_J + min Q_S + mean Q_S) / 4,  each Q_J, Q_S in [0, 1] when valid.
// A mesh is invalid when a cell of any block is folded, inverted or degenerate (a corner
// that is not convex with positive area) or an O-block node has J <= 0; its Q is then
// invalidMeshQuality, below every valid mesh.
//
// Cell (i, j) of a block is the one with nodes i..i+1, j..j+1 (the cell with corners
// (i, j+1), (i+1, j+1), (i+1, j), (i, j) in method.md's numbering, which counts cells by
// their upper row).
#include <cstdint>
#include <string>
#include <vector>

#include "passageMesh/quality/OBlockNeighbours.hpp"
#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

// The reward of an invalid mesh: below the [0, 1] of every valid one.
inline constexpr double invalidMeshQuality = -1.0;

struct CellLocation {
  int block = -1, i = -1, j = -1;
  double x = 0, y = 0;  // the mean of its four corners [m]
};

// Over the cells of one block. For an invalid mesh the values are still those computed
// (Q_J of a cell with a non-positive corner J may be negative), for diagnosis.
struct QualityStatistics {
  double QJmin = 0, QJavg = 0, QSmin = 0, QSavg = 0;
  CellLocation worstQJ, worstQS;  // the cells of QJmin and QSmin
};

struct MeshQuality : QualityStatistics {  // the O-block's statistics, of which Q is made
  double Q = invalidMeshQuality;
  bool valid = false;
  std::string problem;  // the first reason the mesh is invalid (empty when valid)

  // Only with MeshQualityOptions::everyBlock: the statistics of every block (the O-block's
  // again; an H-block's J uses one-sided differences on all its edges, see
  // docs/quality.md), and Q_J, Q_S of every cell, [block][i + (ni - 1) * j].
  std::vector<QualityStatistics> blocks;
  std::vector<std::vector<double>> cellQJ, cellQS;
};

struct MeshQualityOptions {
  bool everyBlock = false;  // also fill MeshQuality::blocks, cellQJ, cellQS (reports, VTK)
};

// Scratch storage reused between calls: after the first call on a mesh of a given size
// the computation allocates nothing (apart from MeshQuality::problem for an invalid mesh
// and the per-block results of everyBlock).
struct MeshQualityWorkspace {
  OBlockNeighbours neighbours;
  // After a call without everyBlock: the O-block's node J, [i + ni * j] (for inspection).
  std::vector<double> jacobian;
  std::vector<double> ghostX, ghostY;
  std::vector<std::uint8_t> ghostKnown;
};

// Throws std::invalid_argument when the mesh has no block named "OBlock", a block with
// fewer than 2 x 2 nodes or wrongly sized coordinate arrays, or a malformed connection.
MeshQuality computeMeshQuality(const StructuredMesh& mesh, MeshQualityWorkspace& workspace,
                               const MeshQualityOptions& options = {});
MeshQuality computeMeshQuality(const StructuredMesh& mesh, const MeshQualityOptions& options = {});

}  // namespace passageMesh
