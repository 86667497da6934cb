#pragma once
// Full approximation scheme (FAS) multigrid for ThompsonSolver's equations on an O-block:
// V-cycles whose smoother is ThompsonSolver's alternating line sweep. A coarse grid takes
// every other i (the last interval of an odd loop spans one fine interval) and every other
// moving row, counted from the last fixed row below (the last interval below the fixed rows
// above may span one fine row), so every fixed row is a row of every grid. Coarse-grid
// corrections that would fold a cell are halved until none does (method.md: "a
// coarse-grid correction folded it").
//
// Single-grid line relaxation converges at about 0.99 per sweep on the tutorials' 300 x 100
// O-blocks (the slow mode runs around the blade); the V-cycle removes that mode on the
// coarse grids (docs/elliptic-smoothing.md has the measured rates).
#include "passageMesh/structured/StructuredMesh.hpp"
#include "passageMesh/mesh/ThompsonSolver.hpp"

namespace passageMesh {

struct MultigridOptions {
  int maxCycles = 100;
  double tolerance = 1e-6;   // thompsonResidual of the finest grid at convergence
  int preSweeps = 2, postSweeps = 2;
  int coarsestSweeps = 20;
  double relaxation = 1.0;   // line relaxation of the smoothing sweeps
  MovingRows rows;
  int coarsestLoop = 16;     // coarsen i only while the coarse loop keeps this many nodes
  int coarsestMovingRows = 4;  // coarsen j only while this many moving rows remain
  // Stop when the residual has not halved over this many cycles (0: never). A working
  // V-cycle gains a factor 2 or more per cycle; a stalled one (a folding grid) would
  // otherwise run all maxCycles (docs/elliptic-smoothing.md).
  int stallCycles = 10;
};

struct MultigridReport {
  int cycles = 0;
  double residual = 0;
  bool converged = false;
  int levels = 1;
};

// `update`, when given, is called before every cycle with the finest grid and may change
// the control functions (the coarse grids' follow).
MultigridReport solveThompsonMultigrid(StructuredBlock& oBlock, GridControl& control,
                                       const MultigridOptions& options = {},
                                       const ControlUpdate& update = {});

}  // namespace passageMesh
