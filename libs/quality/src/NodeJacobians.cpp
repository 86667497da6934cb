#include "passageMesh/quality/NodeJacobians.hpp"

namespace passageMesh {
namespace {

// d f / d(index) at position `at` of a line of n values spaced `stride` apart, with
// one-sided second-order differences at the ends (first-order when n == 2).
inline double endDifference(const double* f, int stride, int n, bool atStart) {
  if (n == 2) return f[stride] - f[0];
  if (atStart) return -1.5 * f[0] + 2 * f[stride] - 0.5 * f[2 * stride];
  const double* e = f + (n - 1) * stride;
  return 1.5 * e[0] - 2 * e[-stride] + 0.5 * e[-2 * stride];
}

}  // namespace

void nodeJacobians(const StructuredBlock& b, bool wrapI, const GhostRow* ghost, double* jacobian) {
  const int ni = b.ni, nj = b.nj;
  const double* x = b.x.data();
  const double* y = b.y.data();
  for (int j = 0; j < nj; ++j) {
    const double* xr = x + ni * j;
    const double* yr = y + ni * j;
    double* jr = jacobian + ni * j;
    // Row pointers for the eta difference of this row: central (p, m) or one-sided.
    const bool central = j > 0 && j < nj - 1;
    const double* xp = central ? xr + ni : nullptr;
    const double* xm = central ? xr - ni : nullptr;
    const double* yp = central ? yr + ni : nullptr;
    const double* ym = central ? yr - ni : nullptr;
    auto xEta = [&](int i) {
      if (central) return 0.5 * (xp[i] - xm[i]);
      if (j == nj - 1 && ghost && ghost->known[i]) return 0.5 * (ghost->x[i] - xr[i - ni]);
      return endDifference(x + i, ni, nj, j == 0);
    };
    auto yEta = [&](int i) {
      if (central) return 0.5 * (yp[i] - ym[i]);
      if (j == nj - 1 && ghost && ghost->known[i]) return 0.5 * (ghost->y[i] - yr[i - ni]);
      return endDifference(y + i, ni, nj, j == 0);
    };
    for (int i = 1; i < ni - 1; ++i)
      jr[i] = 0.5 * (xr[i + 1] - xr[i - 1]) * yEta(i) - xEta(i) * 0.5 * (yr[i + 1] - yr[i - 1]);
    for (int i : {0, ni - 1}) {
      double xXi, yXi;
      if (wrapI && ni > 2) {  // i = 0 and i = ni - 1 are one node: neighbours ni - 2 and 1
        xXi = 0.5 * (xr[1] - xr[ni - 2]);
        yXi = 0.5 * (yr[1] - yr[ni - 2]);
      } else {
        xXi = endDifference(xr, 1, ni, i == 0);
        yXi = endDifference(yr, 1, ni, i == 0);
      }
      jr[i] = xXi * yEta(i) - xEta(i) * yXi;
    }
  }
}

}  // namespace passageMesh
