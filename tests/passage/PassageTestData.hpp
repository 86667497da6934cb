#pragma once
#include "passageMesh/passage/PassageCondition.hpp"

namespace passageMesh::testData {

// The paper's test condition (method.md section 5) at LS89's pitch ratio, for a chord C.
inline PassageCondition paperCondition(double chord) {
  PassageCondition c;
  c.pitch = 0.85 * chord;
  c.xIn = c.xOut = 0.5 * chord;
  c.nO = 30000;
  c.firstCellHeight = 1.1e-4 * chord;
  return c;
}

}  // namespace passageMesh::testData
