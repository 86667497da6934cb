#pragma once
// Small blocks for the structured-mesh tests.
#include <string>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh::testData {

// ni x nj nodes, spacing dx along i and dy along j, sheared by `shear` x per unit y.
inline StructuredBlock uniformBlock(const std::string& name, int ni, int nj, double dx = 1,
                                    double dy = 1, double shear = 0) {
  StructuredBlock b;
  b.name = name;
  b.ni = ni;
  b.nj = nj;
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i < ni; ++i) {
      b.x.push_back(i * dx + shear * j * dy);
      b.y.push_back(j * dy);
    }
  return b;
}

}  // namespace passageMesh::testData
