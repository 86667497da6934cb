#pragma once
// The O-block of an annulus between two concentric circles, shared by the solver and the
// line-redistribution tests.
#include <cmath>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh::testData {

inline constexpr double innerRadius = 1.0, outerRadius = 4.0;

// Uniform radii, clockwise i, j outwards; `wobble` displaces the inner nodes radially so
// the start is not the answer.
inline StructuredBlock annulus(int n, int nj, double wobble = 0) {
  StructuredBlock o;
  o.name = "OBlock";
  o.ni = n + 1;
  o.nj = nj;
  o.x.resize(static_cast<std::size_t>(o.ni) * nj);
  o.y.resize(o.x.size());
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i <= n; ++i) {
      const double theta = -2 * M_PI * (i % n) / n;
      const double s = j / (nj - 1.0);
      const double r = innerRadius + (outerRadius - innerRadius) * s +
                       wobble * std::sin(7 * theta) * std::sin(M_PI * s);
      o.xAt(i, j) = r * std::cos(theta);
      o.yAt(i, j) = r * std::sin(theta);
    }
  return o;
}

}  // namespace passageMesh::testData
