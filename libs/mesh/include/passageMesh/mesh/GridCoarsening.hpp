#pragma once
// The coarse grid of an O-block for multigrid and for solving the control functions on a
// cheaper grid: every other i (the last interval of an odd loop spans one fine interval)
// and every other moving row, counted from the last fixed row below (the last interval
// below the fixed rows above may span one fine row), so that every fixed row is a row of
// the coarse grid too. Coarse node (I, J) is fine node (fineI(I), fineRowOf[J]).
#include <vector>

#include "passageMesh/structured/StructuredMesh.hpp"
#include "passageMesh/mesh/ThompsonSolver.hpp"

namespace passageMesh {

struct Coarsening {
  bool i = false, j = false;
  std::vector<int> fineRowOf;          // per coarse row
  std::vector<int> rowBelow;           // per fine row: the coarse row at or below it
  std::vector<double> rowWeightAbove;  // per fine row: interpolation weight of rowBelow + 1

  bool any() const { return i || j; }
  int fineI(int coarseI) const { return i ? 2 * coarseI : coarseI; }
  int coarseLoop(int fineLoop) const { return i ? (fineLoop + 1) / 2 : fineLoop; }
  // Loop nodes are per index step: a coarsened direction doubles a control function
  // (phi along i, psi along j) and multiplies the equations' residual by 4.
  double residualScale() const { return (i ? 4.0 : 1.0) * (j ? 4.0 : 1.0); }
};

// Coarsens i while the coarse loop keeps at least `coarsestLoop` nodes and j while at
// least `coarsestMovingRows` moving rows remain.
Coarsening coarseningOf(const StructuredBlock& fine, const MovingRows& rows, int coarsestLoop,
                        int coarsestMovingRows);

// The coarse grid's nodes, taken from the fine grid (the seam repeated).
StructuredBlock coarseBlock(const StructuredBlock& fine, const Coarsening& c);

// The fine grid's displacement on the moving rows (index i + ni j, zero elsewhere),
// interpolated bilinearly in index space from the coarse displacement `after - before`.
void interpolateDisplacement(const StructuredBlock& before, const StructuredBlock& after,
                             const Coarsening& c, const StructuredBlock& fine,
                             const MovingRows& rows, std::vector<double>& dx,
                             std::vector<double>& dy);

}  // namespace passageMesh
