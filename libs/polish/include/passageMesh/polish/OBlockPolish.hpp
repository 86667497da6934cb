#pragma once
// A final polish of the O-block by optimisation (docs/elliptic-smoothing.md, "Polish"):
// every node above the held wall rows and below the outer row moves at once so as to
// minimise, by sparse Levenberg-Marquardt (Ceres),
//
//   sum over the cells' corners      (skewWeight |cot(angle)|^skewPower)^2
//   + sum over neighbouring nodes     (jacobianWeight (ln J1 - ln J2 - t))^2
//   + sum over nodes, along rows and lines  |smoothWeight (D2 P - D2 P0) / h|^2
//
// cot(angle) is zero at a right angle and grows without bound as a corner closes, so the
// first sum pulls hardest on the most skewed cells (Q_S). J is a node's central-difference
// Jacobian with Q's neighbour rules across the outer boundary (OBlockNeighbours.hpp); t is
// 0 between nodes of a row (equal Jacobians: Q_J) and, between rows, the value at the
// pass's start (the wall clustering stays). D2 P is a node's second difference along a row or a
// line, D2 P0 the one the pass starts from, h the spacing there: the angles and the central-difference
// Jacobians do not see a zig-zag of alternate rows or a crease of the lines, this term
// does. It includes each line's outer node, whose neighbour beyond is the periodic image of
// the partner line's node or the H-block's node: so the lines stay continued across the
// periodic cut and the interfaces, which Q does not see and a flow solver does. Minimising a smooth surrogate of the quality, rather than Q itself (minima and
// maxima, not differentiable), is optimisation-based mesh smoothing as in Knupp,
// "Achieving finite element mesh quality via optimization of the Jacobian matrix norm and
// associated quantities", Int. J. Numer. Meth. Eng. 48, 2000. The elliptic solve fixes
// each line's two ends, so lines lean where their ends do not face each other; the polish
// spreads that lean over the block instead of leaving it in a band.
//
// What stays exactly as it was: the wall row and the next heldWallRows rows (first cell
// height, wall orthogonality; in the window passes, beside a sharp edge's tip, only row 1),
// the outer row (periodic pairs and interface nodes, so the H-blocks), the H-blocks. Of
// each pass's steps, the nodes with the highest Q (quality library: an invalid mesh
// scores -1) are kept if that Q is above the pass's start; otherwise the pass leaves the
// mesh untouched. The first pass moves the whole block; the
// next ones (OBlockPolishOptions::windowRounds) only a window round the worst cell, where Q's
// minima are, at a small fraction of the cost.
#include <atomic>
#include <functional>
#include <vector>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

struct OBlockPolishReport;

struct OBlockPolishOptions {
  int iterations = 25;       // Levenberg-Marquardt steps a pass (docs/elliptic-smoothing.md "Polish")
  int patience = 5;          // once Q has risen, stop after this many steps without a new
                             // highest Q (0: never)
  int heldWallRows = 3;      // rows 1 .. heldWallRows kept with the wall row, except that
                             // in the window passes rows 2 .. heldWallRows move within
                             // sharpEdgeColumns columns of a wall node where the wall turns
                             // by more than sharpEdgeAngle degrees (a sharp edge's tip)
  double sharpEdgeAngle = 40;  // [degrees]
  int sharpEdgeColumns = 2;
  double skewWeight = 1;
  double skewPower = 2;
  double jacobianWeight = 10;
  double smoothWeight = 10;  // second differences held: 1 or 3 raise Q more but crease the lines
  // After the pass over the whole O-block, up to windowRounds rounds of a pass over the
  // nodes within a half width (in i round the loop, and in j) of the worst Q_S cell's
  // first node (i, j), or where that does not raise Q, of the worst Q_J cell's; the widths
  // in turn, widest first (a wide window spreads a change, a narrow one reaches a single
  // cell the wide one trades away); they stop at the first round that raises none.
  int windowRounds = 20;
  std::vector<int> windowHalfWidths{30, 5};
  // Progress and interruption (ellipticMesh and policyMesh print a line for each pass that
  // raises Q and stop on Ctrl-C): afterStep is called after every step, once its Q is in
  // the report, afterPass after every pass; a non-null `stop` that turns true ends the
  // polish after the step under way, with the best nodes so far kept as usual.
  std::function<void(const OBlockPolishReport&)> afterStep;
  std::function<void(const OBlockPolishReport&)> afterPass;
  const std::atomic<bool>* stop = nullptr;
};

// One Levenberg-Marquardt run of the polish.
struct PolishPass {
  int halfWidth = 0;          // 0: the whole O-block; else a window of this half width
  int i = -1, j = -1;         // the window's centre: the first node of the cell it is round
  bool raised = false;        // some step's Q beat the best before the pass (its nodes kept)
  double qualityAfter = -1;   // the highest Q after the pass
  double seconds = 0;         // since the polish began
};

struct OBlockPolishReport {
  bool kept = false;          // the polished nodes replaced the mesh's
  int iterations = 0;         // their steps in all (a run stops before `iterations` when it
                              // converges, or `patience` steps after its highest Q)
  int bestStep = 0;           // the step (counted over all passes) whose nodes have the
                              // highest Q (0: none above the start)
  double qualityBefore = -1;  // Q of the mesh as given
  double qualityAfter = -1;   // the highest Q of the steps' nodes (kept), or qualityBefore
  double seconds = 0;         // wall time of the polish
  std::vector<double> stepQuality;  // Q of each step's nodes, in order, over all passes (-1: invalid)
  std::vector<PolishPass> passLog;  // every Levenberg-Marquardt run in order: the whole
                                    // block, then the windows (a run stopped before its
                                    // first step is none)
  bool interrupted = false;   // options.stop ended the polish early

  int passes() const { return static_cast<int>(passLog.size()); }
};

// Polishes the O-block ("OBlock") of `mesh` in place. Throws std::invalid_argument when the
// mesh has no O-block or too few rows to move any (fewer than heldWallRows + 3).
OBlockPolishReport polishOBlock(StructuredMesh& mesh, const OBlockPolishOptions& options = {});

}  // namespace passageMesh
