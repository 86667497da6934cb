#pragma once
// The two measures of one quadrilateral cell (method.md section 5), inline because
// computeMeshQuality evaluates them for every cell of every mesh an optimiser tries.
//
// Corners are given counterclockwise in index space, as for cellIsValid
// (passageMesh/structured/CellValidity.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "passageMesh/structured/CellValidity.hpp"

namespace passageMesh {

// Q_J = min / max of the node Jacobians at the four corners.
inline double jacobianRatio(const CellCorners& cornerJ) {
  const double lo = std::min(std::min(cornerJ[0], cornerJ[1]), std::min(cornerJ[2], cornerJ[3]));
  const double hi = std::max(std::max(cornerJ[0], cornerJ[1]), std::max(cornerJ[2], cornerJ[3]));
  return lo / hi;
}

// The shape of a cell from its corners: the skewness quality and whether every corner is
// convex with positive area (cellIsValid: a folded, inverted or degenerate cell is not).
struct CellShape {
  double skewQuality = 0;  // Q_S
  bool convex = false;
};

// Q_S = 1 - max((90 - min angle) / 90, (max angle - 90) / 90), angles in degrees.
// With c = cos(angle): 90 - angle = asin(c) (in degrees), so the bracket is
// asin(max(c_max, -c_min)) / 90 degrees; one asin per cell instead of four acos.
inline CellShape cellShape(const CellCorners& x, const CellCorners& y) {
  double ex[4], ey[4], length2[4];
  for (int k = 0; k < 4; ++k) {
    ex[k] = x[(k + 1) % 4] - x[k];
    ey[k] = y[(k + 1) % 4] - y[k];
    length2[k] = ex[k] * ex[k] + ey[k] * ey[k];
  }
  double cosMax = -1, cosMin = 1;
  for (int k = 0; k < 4; ++k) {
    const int previous = (k + 3) % 4;  // corner k joins edge `previous` (arriving) and edge k
    const double cosine = -(ex[previous] * ex[k] + ey[previous] * ey[k]) /
                          std::sqrt(length2[previous] * length2[k]);
    cosMax = std::max(cosMax, cosine);
    cosMin = std::min(cosMin, cosine);
  }
  const double deviation = std::clamp(std::max(cosMax, -cosMin), -1.0, 1.0);
  return {1 - std::asin(deviation) * (2 / std::numbers::pi), cellIsValid(x, y)};
}

}  // namespace passageMesh
