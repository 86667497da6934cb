#pragma once
// Elliptic smoothing of the O-block (method.md section 4, docs/elliptic-smoothing.md).
//
// Fixed: the wall row j = 0, the first row j = 1 (each node exactly firstCellHeight from
// its wall node: the first cell height is exact by construction) and the outer row.
// Moving: rows 2 .. nj - 2, by ThompsonSolver (Thomas-Middlecoff form) with
//   phi(i, j) = phiWall(i) (1 - s)^3 + phiOuter(i) s^3,     s = (j - 1) / (nj - 2),
//   psi(i, j) = psiLine(i, j) + (psiOuter(i) - psiLine(i, nj - 2)) s^3,
// where
//   phiWall   = -t_xixi / t_xi of the wall node distribution (arc length t),
//   psiLine   = -s_etaeta / s_eta of the initial (algebraic) line: it keeps the wall
//               clustering solved for the first cell height,
//   phiOuter, psiOuter = Sorenson's boundary control at the outer loop: the values that
//               make the equations at the outer row hold for lines leaving it
//               orthogonally with the initial outer spacing; updated every sweep with
//               under-relaxation as the grid converges. Orthogonality at the outer loop is
//               what keeps the grid unfolded at its re-entrant corners (the kink where a
//               camber-following periodic boundary meets the straight outlet part).
#include "passageMesh/mesh/StructuredMesh.hpp"
#include "passageMesh/mesh/ThompsonSolver.hpp"

namespace passageMesh {

struct EllipticOptions {
  int maxSweeps = 4000;
  double tolerance = 1e-6;          // ThompsonReport::residual at convergence
  double lineRelaxation = 1.3;      // ThompsonOptions::relaxation
  // Each sweep moves the outer control values this fraction of the way to the values the
  // outer-row equations ask for (0.2 already diverged on the tutorials).
  double controlRelaxation = 0.1;
  // |phi|, |psi| above 2 make the line systems lose diagonal dominance.
  double controlLimit = 1.0;
};

struct EllipticReport {
  int sweeps = 0;
  double residual = 0;
  bool converged = false;
};

// `oBlock`: ni = nT + 1 (seam repeated), nj >= 4 rows, as buildHohMesh makes it.
EllipticReport smoothOBlock(StructuredBlock& oBlock, const EllipticOptions& options = {});

}  // namespace passageMesh
