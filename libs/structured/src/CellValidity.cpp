#include "passageMesh/structured/CellValidity.hpp"

#include <algorithm>

namespace passageMesh {

namespace {

// The first invalid cell (i, j) of `block` from row `firstRow` up, j-major then i; false
// when every one is valid.
bool firstInvalidCell(const StructuredBlock& block, int firstRow, int& cellI, int& cellJ) {
  CellCorners x, y;
  for (int j = std::max(0, firstRow); j + 1 < block.nj; ++j)
    for (int i = 0; i + 1 < block.ni; ++i) {
      cellCorners(block, i, j, x, y);
      if (!cellIsValid(x, y)) {
        cellI = i;
        cellJ = j;
        return true;
      }
    }
  return false;
}

}  // namespace

std::string findInvalidCell(const StructuredBlock& block) {
  int i = 0, j = 0;
  if (!firstInvalidCell(block, 0, i, j)) return "";
  return block.name + " cell (" + std::to_string(i) + ", " + std::to_string(j) + ") is folded or degenerate";
}

bool cellsValidFrom(const StructuredBlock& block, int firstRow) {
  int i = 0, j = 0;
  return !firstInvalidCell(block, firstRow, i, j);
}

std::string findInvalidCell(const StructuredMesh& mesh) {
  for (const auto& block : mesh.blocks)
    if (std::string problem = findInvalidCell(block); !problem.empty()) return problem;
  return "";
}

}  // namespace passageMesh
