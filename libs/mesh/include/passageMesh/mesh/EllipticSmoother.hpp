#pragma once
// Elliptic smoothing of the O-block (method.md section 4, docs/elliptic-smoothing.md).
//
// Fixed: the wall row j = 0, the wall layer j = 1 .. L (row 1 exactly firstCellHeight from
// its wall node, so the first cell height is exact by construction; L = wallLayerRows, at
// most nj / wallLayerFraction) and the outer loop. Moving: rows L + 1 .. nj - 2, by
// ThompsonSolver's equations (Thomas-Middlecoff form) with
//   phi(i, j) = phiWall(i) (1 - s)^3 + phiOuter(i) s^3,                 s = (j - 1) / (nj - 2)
//   psi(i, j) = psiLine(i, j) + (psiOuter(i) - psiLine(i, nj - 2)) s^3,
// where
//   phiWall   = -t_xixi / t_xi of the wall node distribution (arc length t),
//   psiLine   = -s_etaeta / s_eta of the initial (algebraic) line: it keeps the wall
//               clustering solved for the first cell height,
//   phiOuter, psiOuter = Sorenson's boundary control at the outer loop: the values that
//               make the outer-row equations hold for lines leaving the loop orthogonally
//               with the initial outer spacing. They depend on the grid they shape, so
//               they are found by under-relaxed iteration together with the grid, on a
//               coarse copy of the O-block (cheap, and this coupled iteration is only
//               stable with slowly converging sweeps), then carried to the full grid.
// Orthogonality at the outer loop is what keeps the grid unfolded at its re-entrant
// kinks (where a camber-following periodic boundary meets the straight outlet part).
// The full grid is then solved with the control functions fixed, by FAS multigrid
// (ThompsonMultigrid.hpp), or by single-grid line relaxation.
#include "passageMesh/structured/StructuredMesh.hpp"
#include "passageMesh/mesh/ThompsonSolver.hpp"

namespace passageMesh {

struct EllipticOptions {
  // The wall layer: rows 1 .. this many stay where the algebraic grid put them (lines along
  // the smoothed wall normals, clustered for the exact first cell height), at most one
  // row in wallLayerFraction. It keeps the near-wall cells orthogonal, which the equations
  // alone do not (measured Q at the defaults, row 1 only / rows 1-12: LS89 0.358 / 0.376,
  // STD10 0.404 / 0.455, T106A 0.440 / 0.452, SIRT 0.428 / 0.487).
  int wallLayerRows = 12;
  int wallLayerFraction = 8;
  double tolerance = 1e-5;          // ThompsonReport::residual of the full grid
  bool multigrid = true;            // false: single-grid line relaxation on the full grid
  int maxCycles = 100;              // multigrid V-cycles
  int maxSweeps = 5000;             // single-grid sweeps on the full grid
  double lineRelaxation = 1.3;      // line over-relaxation of the single-grid solves
  // The outer control values: solved on the grid coarsened around the loop until it has at
  // most this many nodes (all rows kept), to this residual or for at most this many sweeps
  // (then taken as they are), each sweep moving them this fraction of the way to the values
  // the outer row asks for (0.2 diverged on the tutorials), clipped to this size (above 2
  // the line systems lose diagonal dominance).
  int controlGridLoop = 80;
  double controlTolerance = 1e-4;
  int controlMaxSweeps = 400;
  double controlRelaxation = 0.05;
  double controlLimit = 1.0;
};

struct EllipticReport {
  int iterations = 0;      // V-cycles (multigrid) or sweeps on the full grid
  int controlSweeps = 0;   // sweeps of the coarse grid that found the outer control values
  double residual = 0;
  bool converged = false;
};

// `oBlock`: ni = nT + 1 (seam repeated), nj >= 4 rows, as buildHohMesh makes it.
EllipticReport smoothOBlock(StructuredBlock& oBlock, const EllipticOptions& options = {});

}  // namespace passageMesh
