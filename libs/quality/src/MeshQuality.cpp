#include "passageMesh/quality/MeshQuality.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "passageMesh/quality/CellQuality.hpp"
#include "passageMesh/quality/NodeJacobians.hpp"

namespace passageMesh {
namespace {

void checkBlock(const StructuredBlock& b) {
  const auto count = static_cast<std::size_t>(b.ni) * static_cast<std::size_t>(b.nj);
  if (b.ni < 2 || b.nj < 2 || b.x.size() != count || b.y.size() != count)
    throw std::invalid_argument("mesh quality: block '" + b.name +
                                "' needs at least 2 x 2 nodes and ni * nj coordinates");
}

std::string cellName(const StructuredBlock& b, int i, int j) {
  return b.name + " cell (" + std::to_string(i) + ", " + std::to_string(j) + ")";
}

CellLocation locate(const StructuredBlock& b, int block, int i, int j) {
  if (i < 0) return {};
  const double x = b.xAt(i, j) + b.xAt(i + 1, j) + b.xAt(i + 1, j + 1) + b.xAt(i, j + 1);
  const double y = b.yAt(i, j) + b.yAt(i + 1, j) + b.yAt(i + 1, j + 1) + b.yAt(i, j + 1);
  return {block, i, j, 0.25 * x, 0.25 * y};
}

// Q_J and Q_S over the cells of one block (Q_J only when `jacobian` is given). Returns
// false when a cell is not convex with positive area or, with `jacobianMustBePositive`,
// has a corner with J <= 0; the first such cell is described in `problem`.
// cellQJ, cellQS (may be null) receive the per-cell values.
bool blockStatistics(const StructuredBlock& b, int block, const double* jacobian,
                     bool jacobianMustBePositive, QualityStatistics& s, std::string& problem,
                     double* cellQJ, double* cellQS) {
  const int ni = b.ni, nj = b.nj;
  double sumJ = 0, sumS = 0;
  double minJ = std::numeric_limits<double>::infinity(), minS = minJ;
  int worstJ[2] = {-1, -1}, worstS[2] = {-1, -1};
  bool valid = true;
  for (int j = 0; j + 1 < nj; ++j) {
    const int lower = ni * j, upper = lower + ni;
    for (int i = 0; i + 1 < ni; ++i) {
      const int n[4] = {lower + i, lower + i + 1, upper + i + 1, upper + i};
      const CellCorners x{b.x[n[0]], b.x[n[1]], b.x[n[2]], b.x[n[3]]};
      const CellCorners y{b.y[n[0]], b.y[n[1]], b.y[n[2]], b.y[n[3]]};
      const CellShape shape = cellShape(x, y);
      const int cell = i + (ni - 1) * j;
      sumS += shape.skewQuality;
      if (shape.skewQuality < minS) minS = shape.skewQuality, worstS[0] = i, worstS[1] = j;
      if (cellQS) cellQS[cell] = shape.skewQuality;
      bool cellValid = shape.convex;
      if (jacobian) {
        const CellCorners corner{jacobian[n[0]], jacobian[n[1]], jacobian[n[2]], jacobian[n[3]]};
        const double qJ = jacobianRatio(corner);
        if (jacobianMustBePositive)
          cellValid = cellValid && corner[0] > 0 && corner[1] > 0 && corner[2] > 0 && corner[3] > 0;
        sumJ += qJ;
        if (qJ < minJ) minJ = qJ, worstJ[0] = i, worstJ[1] = j;
        if (cellQJ) cellQJ[cell] = qJ;
      }
      if (!cellValid && valid) {
        valid = false;
        problem = cellName(b, i, j) + (shape.convex ? " has a corner node with J <= 0"
                                                      : " is folded, inverted or degenerate");
      }
    }
  }
  const double cells = static_cast<double>(ni - 1) * (nj - 1);
  s.QSmin = minS;
  s.QSavg = sumS / cells;
  s.worstQS = locate(b, block, worstS[0], worstS[1]);
  if (jacobian) {
    s.QJmin = minJ;
    s.QJavg = sumJ / cells;
    s.worstQJ = locate(b, block, worstJ[0], worstJ[1]);
  }
  return valid;
}

// The nodes of the row beyond the O-block's outer row, from the connections.
GhostRow fillGhostRow(const StructuredMesh& mesh, MeshQualityWorkspace& w) {
  const auto& outer = w.neighbours.outer;
  w.ghostX.resize(outer.size());
  w.ghostY.resize(outer.size());
  w.ghostKnown.resize(outer.size());
  for (std::size_t i = 0; i < outer.size(); ++i) {
    const OuterNeighbour& n = outer[i];
    w.ghostKnown[i] = n.block >= 0;
    if (n.block < 0) continue;
    const StructuredBlock& d = mesh.blocks[static_cast<std::size_t>(n.block)];
    w.ghostX[i] = d.x[static_cast<std::size_t>(n.node)] + n.dx;
    w.ghostY[i] = d.y[static_cast<std::size_t>(n.node)] + n.dy;
  }
  return {w.ghostX.data(), w.ghostY.data(), w.ghostKnown.data()};
}

}  // namespace

MeshQuality computeMeshQuality(const StructuredMesh& mesh, MeshQualityWorkspace& w,
                               const MeshQualityOptions& options) {
  for (const StructuredBlock& b : mesh.blocks) checkBlock(b);
  findOBlockNeighbours(mesh, w.neighbours);
  const int oBlock = w.neighbours.oBlock;
  const GhostRow ghost = fillGhostRow(mesh, w);

  MeshQuality q;
  const std::size_t blockCount = mesh.blocks.size();
  if (options.everyBlock) {
    q.blocks.resize(blockCount);
    q.cellQJ.resize(blockCount);
    q.cellQS.resize(blockCount);
  }
  bool valid = true;
  for (std::size_t b = 0; b < blockCount; ++b) {
    const StructuredBlock& block = mesh.blocks[b];
    const bool isO = static_cast<int>(b) == oBlock;
    const double* jacobian = nullptr;
    if (isO || options.everyBlock) {
      w.jacobian.resize(block.x.size());
      nodeJacobians(block, isO && w.neighbours.wrapI, isO ? &ghost : nullptr, w.jacobian.data());
      jacobian = w.jacobian.data();
    }
    double* cellQJ = nullptr;
    double* cellQS = nullptr;
    if (options.everyBlock) {
      const auto cells = static_cast<std::size_t>(block.ni - 1) * static_cast<std::size_t>(block.nj - 1);
      q.cellQJ[b].resize(cells);
      q.cellQS[b].resize(cells);
      cellQJ = q.cellQJ[b].data();
      cellQS = q.cellQS[b].data();
    }
    QualityStatistics statistics;
    std::string problem;
    // Other blocks' J comes from one-sided differences on all their edges: a report only,
    // their validity is by cell shape.
    if (!blockStatistics(block, static_cast<int>(b), jacobian, isO, statistics, problem, cellQJ,
                         cellQS)) {
      valid = false;
      if (q.problem.empty()) q.problem = problem;
    }
    if (isO) static_cast<QualityStatistics&>(q) = statistics;
    if (options.everyBlock) q.blocks[b] = statistics;
  }
  q.valid = valid;
  q.Q = valid ? (q.QJmin + q.QJavg + q.QSmin + q.QSavg) / 4 : invalidMeshQuality;
  return q;
}

MeshQuality computeMeshQuality(const StructuredMesh& mesh, const MeshQualityOptions& options) {
  MeshQualityWorkspace workspace;
  return computeMeshQuality(mesh, workspace, options);
}

}  // namespace passageMesh
