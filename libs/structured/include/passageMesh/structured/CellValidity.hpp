#pragma once
// The one cell-validity check of a structured mesh: a quadrilateral cell is valid when
// every corner is convex with positive area. HohMesh uses it to refuse a folded mesh
// (findInvalidCell), and the quality Q (libs/quality) to call a mesh invalid.
//
// Corners are given counterclockwise in index space: (i, j), (i + 1, j), (i + 1, j + 1),
// (i, j + 1) of the cell whose lowest node is (i, j); in a right-handed block (every block
// of a valid HOH mesh) they then run counterclockwise in space too.
#include <array>
#include <string>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

using CellCorners = std::array<double, 4>;

// True when at every corner k the cross product of the arriving edge (corner k - 1 to k)
// and the leaving edge (k to k + 1) is positive; false for a folded, inverted or
// degenerate cell, and for NaN coordinates. Inline: the quality evaluates it for every
// cell of every mesh an optimiser tries.
inline bool cellIsValid(const CellCorners& x, const CellCorners& y) {
  for (int k = 0; k < 4; ++k) {
    const int previous = (k + 3) % 4, next = (k + 1) % 4;
    const double inX = x[k] - x[previous], inY = y[k] - y[previous];
    const double outX = x[next] - x[k], outY = y[next] - y[k];
    if (!(inX * outY - inY * outX > 0)) return false;
  }
  return true;
}

// The corners of cell (i, j) of `block`, in cellIsValid's order.
inline void cellCorners(const StructuredBlock& block, int i, int j, CellCorners& x,
                        CellCorners& y) {
  x = {block.xAt(i, j), block.xAt(i + 1, j), block.xAt(i + 1, j + 1), block.xAt(i, j + 1)};
  y = {block.yAt(i, j), block.yAt(i + 1, j), block.yAt(i + 1, j + 1), block.yAt(i, j + 1)};
}

// The first invalid cell, blocks in order and in each block j-major then i, as
// "<block> cell (i, j) is folded or degenerate"; empty when every cell is valid.
std::string findInvalidCell(const StructuredMesh& mesh);
// The same for one block (no mesh around it to build: HohMesh checks its O-block alone).
std::string findInvalidCell(const StructuredBlock& block);

// True when every cell of `block` from row `firstRow` up is valid: the multigrid's test of
// a coarse-grid correction, which needs no location.
bool cellsValidFrom(const StructuredBlock& block, int firstRow);

}  // namespace passageMesh
