#pragma once
// Thompson's elliptic grid equations on an O-block (method.md section 4), written in the
// Thomas-Middlecoff form
//   alpha (x_xixi + phi x_xi) - 2 beta x_xieta + gamma (x_etaeta + psi x_eta) = 0
//   (the same for y), alpha = x_eta^2 + y_eta^2, beta = x_xi x_eta + y_xi y_eta,
//   gamma = x_xi^2 + y_xi^2, J = x_xi y_eta - x_eta y_xi.
// It is method.md's Poisson system with P = alpha phi / J^2 and Q = gamma psi / J^2: the
// same equations, but phi and psi are dimensionless (psi = -s_etaeta / s_eta along a
// straight line whose nodes sit at arc lengths s), so they can be blended between the wall
// and the outer boundary without carrying the 1/dn1^2 scale of the wall layer into the
// far field (docs/elliptic-smoothing.md).
//
// Central differences with unit index spacing; i is periodic (the seam node i = ni - 1
// repeats i = 0); only the rows of MovingRows move. A sweep is one
// pass of j-line Gauss-Seidel (tridiagonal solves along each i = const line) followed by
// one pass of i-line Gauss-Seidel (cyclic tridiagonal solves around each j = const loop),
// the coefficients frozen at the current grid: the i-lines carry the slow mode around the
// blade that j-lines alone barely damp (method.md, "Measured on this machine kind").
#include <functional>
#include <vector>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

// Control functions at the nodes, index i + (ni - 1) j for i < ni - 1; empty means zero.
// forceX, forceY: a right-hand side for the x and y equations (empty: zero), what the
// coarse grids of the full approximation scheme (ThompsonMultigrid.hpp) solve for.
struct GridControl {
  std::vector<double> phi, psi;
  std::vector<double> forceX, forceY;
};

// The rows a solve moves: j in [below, nj - 1 - above); the `below` rows from the wall and
// the `above` rows at the outer loop stay where they are.
struct MovingRows {
  int below = 1;
  int above = 1;
  int first() const { return below; }
  int last(const StructuredBlock& b) const { return b.nj - 1 - above; }
};

struct ThompsonOptions {
  int maxSweeps = 5000;
  // Converged when residual() is at most this (see ThompsonReport::residual).
  double tolerance = 1e-9;
  MovingRows rows;    // default: all but the wall and the outer row
  bool iLines = true; // alternate j-line and i-line sweeps (false: j-lines only)
  // Each line solve moves its nodes this multiple of the way to the line's solution
  // (successive line over-relaxation; above about 1.5 the cold start diverges).
  double relaxation = 1.0;
};

struct ThompsonReport {
  int sweeps = 0;
  // Largest over the moving nodes of |residual of the two equations| / (2 (alpha + gamma)),
  // the distance a point-Jacobi update would move the node, divided by sqrt(|J|), the
  // local cell size: dimensionless, the same for a scaled grid.
  double residual = 0;
  bool converged = false;
};

// Called before every sweep with the current grid; may update the control functions (the
// wall-layer values of EllipticSmoother) or leave them.
using ControlUpdate = std::function<void(const StructuredBlock&, GridControl&)>;

// Runs `iteration` until `residual()` is at most `tolerance` (converged), is not finite,
// `maxIterations` have run, or (stallWindow > 0) the residual has not halved over the last
// stallWindow iterations: a stalled solve, which does not converge by going on. The loop
// shared by the single-grid and multigrid solvers.
ThompsonReport iterateUntilConverged(int maxIterations, double tolerance,
                                     const std::function<void()>& iteration,
                                     const std::function<double()>& residual, int stallWindow = 0);

ThompsonReport solveThompson(StructuredBlock& oBlock, GridControl& control,
                             const ThompsonOptions& options = {},
                             const ControlUpdate& update = {});

// One sweep (j-lines, then i-lines when iLines) of the moving rows.
void sweepThompson(StructuredBlock& oBlock, const GridControl& control, const MovingRows& rows,
                   double relaxation, bool iLines = true);

// The left-hand side minus the force of both equations at every node of the moving rows
// (index i + (ni - 1) j; other entries untouched). `rx`, `ry` are resized.
void thompsonResidualField(const StructuredBlock& oBlock, const GridControl& control,
                           const MovingRows& rows, std::vector<double>& rx,
                           std::vector<double>& ry);

// The residual measure of ThompsonReport over the moving rows, for the grid as it is: not a
// number where a node of the moving rows, or a neighbour they read, is not a number (or
// gives one, as a collapsed node's 0 / 0).
double thompsonResidual(const StructuredBlock& oBlock, const GridControl& control,
                        const MovingRows& rows);

}  // namespace passageMesh
