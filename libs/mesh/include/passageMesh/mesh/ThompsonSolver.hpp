#pragma once
// Thompson's Poisson grid equations on an O-block (method.md section 4),
//   alpha x_xixi - 2 beta x_xieta + gamma x_etaeta = -J^2 (P x_xi + Q x_eta)
//   (the same for y), alpha = x_eta^2 + y_eta^2, beta = x_xi x_eta + y_xi y_eta,
//   gamma = x_xi^2 + y_xi^2, J = x_xi y_eta - x_eta y_xi,
// discretised with central differences (unit index spacing) and solved by j-line
// Gauss-Seidel: for each i, the nodes of its j-line are updated together by a tridiagonal
// solve with the coefficients frozen at the current grid. i is periodic (the seam node
// i = ni - 1 repeats i = 0); the first `fixedRows` rows from the wall and the outer row
// keep their positions.
//
// This is the solver core. The control functions that keep the wall spacing and
// orthogonality (Hsu-Lee) and the multigrid acceleration are issue 3's remaining work.
#include <vector>

#include "passageMesh/mesh/StructuredMesh.hpp"

namespace passageMesh {

struct ThompsonOptions {
  int maxSweeps = 10000;
  // Converged when the largest node move of a sweep is below tolerance * referenceLength.
  double tolerance = 1e-10;
  double relaxation = 1.0;
  int fixedRows = 1;  // rows j < fixedRows are not moved (1: the wall only)
};

struct ThompsonReport {
  int sweeps = 0;
  double lastMove = 0;  // largest node move of the last sweep / referenceLength
  bool converged = false;
};

// `P`, `Q`: control functions at the nodes i + (ni - 1) j (i < ni - 1), or empty for zero.
ThompsonReport solveThompson(StructuredBlock& oBlock, const std::vector<double>& P,
                             const std::vector<double>& Q, double referenceLength,
                             const ThompsonOptions& options = {});

}  // namespace passageMesh
