#include "passageMesh/structured/CellValidity.hpp"

#include <algorithm>

namespace passageMesh {

std::string findInvalidCell(const StructuredBlock& block) {
  CellCorners x, y;
  for (int j = 0; j + 1 < block.nj; ++j)
    for (int i = 0; i + 1 < block.ni; ++i) {
      cellCorners(block, i, j, x, y);
      if (!cellIsValid(x, y))
        return block.name + " cell (" + std::to_string(i) + ", " + std::to_string(j) +
               ") is folded or degenerate";
    }
  return "";
}

bool cellsValidFrom(const StructuredBlock& block, int firstRow) {
  CellCorners x, y;
  for (int j = std::max(0, firstRow); j + 1 < block.nj; ++j)
    for (int i = 0; i + 1 < block.ni; ++i) {
      cellCorners(block, i, j, x, y);
      if (!cellIsValid(x, y)) return false;
    }
  return true;
}

std::string findInvalidCell(const StructuredMesh& mesh) {
  for (const auto& block : mesh.blocks)
    if (std::string problem = findInvalidCell(block); !problem.empty()) return problem;
  return "";
}

}  // namespace passageMesh
