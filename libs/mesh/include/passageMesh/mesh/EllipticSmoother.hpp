#pragma once
// Elliptic smoothing of the O-block (method.md section 4, docs/elliptic-smoothing.md).
//
// buildHohMesh calls it on an O-block whose rows are evenly spaced along each line (no wall
// clustering; HohMesh.hpp). Fixed: the wall row, an optional wall layer j = 1 .. L
// (L = wallLayerRows, at most nj / wallLayerFraction; 0 by default) and the outer loop.
// Moving: the rows between, by ThompsonSolver's equations (Thomas-Middlecoff form) with
//   phi(i, j) = phiWall(i) (1 - s)^3 + phiOuter(i) s^3,
//   psi(i, j) = psiLine(i, j) + (psiWall(i) - psiLine(i, 1)) (1 - s)^3
//                             + (psiOuter(i) - psiLine(i, nj - 2)) s^3,    s = j / (nj - 1)
// where
//   psiLine   = -s_etaeta / s_eta of the initial (algebraic) line,
//   phiWall, psiWall, phiOuter, psiOuter = Sorenson's boundary control at the wall and at
//               the outer loop: the values that make the boundary rows' equations hold for
//               lines leaving the boundary orthogonally with the initial spacing there.
//               They depend on the grid they shape, so they are found by under-relaxed
//               iteration together with the grid, on a copy of the O-block resampled at
//               fewer nodes around the loop (cheap,
//               and this coupled iteration is only stable with slowly converging sweeps),
//               then carried to the full grid.
// With wallOrthogonality off (the first tool's setting, for wall-clustered grids whose
// 1/dn1^2 scale the wall values do not survive), phiWall is -t_xixi / t_xi of the wall
// node distribution, psiWall is not used and s = (j - 1) / (nj - 2).
// Orthogonality at the outer loop is what keeps the grid unfolded at its re-entrant
// kinks (where a camber-following periodic boundary meets the straight outlet part).
// On the periodic segments (when smoothOBlock is given them) the outer control asks for
// lines that continue through the periodic image instead of arriving square: the target
// direction at a periodic node is the chord from its row nj - 2 node to the image of its
// partner's, turning to the boundary normal next to the four corners
// (periodicContinuationBlend). At an interface square arrival is the continuation into
// the H-block's straight lines, so it stays (docs/elliptic-smoothing.md).
// The full grid is then solved with the control functions fixed, by FAS multigrid
// (ThompsonMultigrid.hpp), or by single-grid line relaxation.
#include <Eigen/Core>
#include <optional>

#include "passageMesh/structured/StructuredMesh.hpp"
#include "passageMesh/mesh/ThompsonSolver.hpp"

namespace passageMesh {

struct EllipticOptions {
  // The wall layer: rows 1 .. this many stay where the algebraic grid put them, at most
  // one row in wallLayerFraction. 0 with wallOrthogonality (docs/elliptic-smoothing.md:
  // a fixed layer kinks the lines at its top).
  int wallLayerRows = 0;
  int wallLayerFraction = 8;
  // Sorenson's control at the wall too (lines leave the wall orthogonally with the initial
  // wall spacing), iterated with the outer values; for grids without wall clustering.
  // Off in buildHohMesh's later tries where the first mesh folds.
  bool wallOrthogonality = true;
  // Sorenson's control at the outer loop (lines arriving square to it with the initial
  // spacing there). Off: the outer values are zero, the lines arrive at the angle the
  // interior gives them; buildHohMesh's second try where the first mesh folds.
  bool outerOrthogonality = true;
  // With the periodic segments given: their lines continue through the periodic image
  // (false: square to the boundary there too), with the target direction turning from the
  // boundary normal at each corner to the continued line's over this fraction of the
  // segment's intervals (smoothstep). 0.2 measured best of 0 (no turn) to 0.5.
  bool periodicContinuation = true;
  double periodicContinuationBlend = 0.2;
  double tolerance = 1e-5;          // ThompsonReport::residual of the full grid
  bool multigrid = true;            // false: single-grid line relaxation on the full grid
  int maxCycles = 100;              // multigrid V-cycles
  int maxSweeps = 5000;             // single-grid sweeps on the full grid
  double lineRelaxation = 1.3;      // line over-relaxation of the single-grid solves
  // The outer control values: solved on the O-block resampled around the loop at this many
  // nodes (fewer when the loop has fewer; all rows kept; the trailing and leading edges
  // among them; 40, 48, 60, 72 and 80 measured: docs/elliptic-smoothing.md), to this
  // residual or for at most this many sweeps
  // (then taken as they are), each sweep moving them this fraction of the way to the values
  // the outer row asks for (0.2 diverged on the tutorials), clipped to this size (above 2
  // the line systems lose diagonal dominance).
  int controlGridLoop = 60;
  double controlTolerance = 1e-4;
  int controlMaxSweeps = 400;
  double controlRelaxation = 0.05;
  double controlLimit = 1.5;
};

struct EllipticReport {
  int iterations = 0;      // V-cycles (multigrid) or sweeps on the full grid
  int controlSweeps = 0;   // sweeps of the coarse grid that found the outer control values
  double residual = 0;
  bool converged = false;
};

// The outer loop's periodic segments (OuterLoop.hpp): outer node lowerBegin + k (k = 0 at
// the outlet corner, lowerEnd at the inlet corner) and upperEnd - k are one periodic
// pair, upper = lower + translation.
struct PeriodicOuterSegments {
  int lowerBegin = 0, lowerEnd = 0, upperBegin = 0, upperEnd = 0;
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();  // [m]
};

// `oBlock`: ni = nT + 1 (seam repeated), nj >= 4 rows, as buildHohMesh makes it.
// `periodic`: the outer loop's periodic segments (none: every outer line arrives square).
// `leadingEdge`: the leading edge's loop node (0: none given). The grid the control values
// are found on (options.controlGridLoop) has the trailing edge (i = 0) and the leading
// edge among its nodes.
EllipticReport smoothOBlock(StructuredBlock& oBlock, const EllipticOptions& options = {},
                            const std::optional<PeriodicOuterSegments>& periodic = std::nullopt,
                            int leadingEdge = 0);

}  // namespace passageMesh
