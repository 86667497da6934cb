#pragma once
// The node Jacobian of method.md section 5 at every node of one block,
//   J(i, j) = x_xi y_eta - x_eta y_xi,
// with central differences in the node indices, (f[i+1] - f[i-1]) / 2. Where a neighbour
// is missing the difference is one-sided and second-order, e.g. at j = 0
//   f_eta = (-3 f[0] + 4 f[1] - f[2]) / 2,   at j = nj - 1: (3 f[nj-1] - 4 f[nj-2] + f[nj-3]) / 2
// (first-order (f[1] - f[0]) when the block has only two nodes in that direction).
#include <cstdint>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

// Nodes of the row j = nj beyond a block's last row, where known.
struct GhostRow {
  const double* x = nullptr;        // ni values each
  const double* y = nullptr;
  const std::uint8_t* known = nullptr;  // 0: no ghost for this i (one-sided there)
};

// Writes J of node (i, j) to jacobian[i + ni * j]. wrapI: nodes i = 0 and i = ni - 1
// coincide (a closed loop), so the neighbours of both are i = 1 and i = ni - 2.
// ghost == nullptr: no ghost row at all.
void nodeJacobians(const StructuredBlock& block, bool wrapI, const GhostRow* ghost,
                   double* jacobian);

}  // namespace passageMesh
