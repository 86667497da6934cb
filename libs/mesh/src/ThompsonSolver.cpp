#include "passageMesh/mesh/ThompsonSolver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace passageMesh {

ThompsonReport solveThompson(StructuredBlock& o, const std::vector<double>& P,
                             const std::vector<double>& Q, double referenceLength,
                             const ThompsonOptions& options) {
  const int n = o.ni - 1, nj = o.nj, J = nj - 1;
  if (n < 3 || nj < 3 || options.fixedRows < 1 || options.fixedRows >= J)
    throw std::invalid_argument("solveThompson: block too small for the fixed rows");
  const std::size_t nodes = static_cast<std::size_t>(n) * nj;
  if ((!P.empty() && P.size() != nodes) || (!Q.empty() && Q.size() != nodes))
    throw std::invalid_argument("solveThompson: control functions of the wrong size");
  auto wrap = [n](int i) { return (i % n + n) % n; };
  auto X = [&](int i, int j) { return o.xAt(wrap(i), j); };
  auto Y = [&](int i, int j) { return o.yAt(wrap(i), j); };

  const int first = options.fixedRows, last = J - 1;  // the unknown rows
  std::vector<double> lower(nj), diagonal(nj), upper(nj), rx(nj), ry(nj);
  ThompsonReport report;
  for (int sweep = 1; sweep <= options.maxSweeps; ++sweep) {
    double largest = 0;
    for (int i = 0; i < n; ++i) {
      for (int j = first; j <= last; ++j) {
        const std::size_t k = static_cast<std::size_t>(i + n * j);
        const double p = P.empty() ? 0.0 : P[k], q = Q.empty() ? 0.0 : Q[k];
        const double xXi = 0.5 * (X(i + 1, j) - X(i - 1, j)), yXi = 0.5 * (Y(i + 1, j) - Y(i - 1, j));
        const double xEta = 0.5 * (X(i, j + 1) - X(i, j - 1)), yEta = 0.5 * (Y(i, j + 1) - Y(i, j - 1));
        const double xXiEta =
            0.25 * (X(i + 1, j + 1) - X(i + 1, j - 1) - X(i - 1, j + 1) + X(i - 1, j - 1));
        const double yXiEta =
            0.25 * (Y(i + 1, j + 1) - Y(i + 1, j - 1) - Y(i - 1, j + 1) + Y(i - 1, j - 1));
        const double alpha = xEta * xEta + yEta * yEta;
        const double beta = xXi * xEta + yXi * yEta;
        const double gamma = xXi * xXi + yXi * yXi;
        const double jac = xXi * yEta - xEta * yXi, j2 = jac * jac;
        // gamma (x_N - 2x + x_S) + J^2 Q (x_N - x_S)/2 on the line, the rest known.
        lower[j] = gamma - 0.5 * j2 * q;
        upper[j] = gamma + 0.5 * j2 * q;
        diagonal[j] = -2 * (alpha + gamma);
        rx[j] = -(alpha * (X(i + 1, j) + X(i - 1, j)) - 2 * beta * xXiEta + j2 * p * xXi);
        ry[j] = -(alpha * (Y(i + 1, j) + Y(i - 1, j)) - 2 * beta * yXiEta + j2 * p * yXi);
      }
      rx[first] -= lower[first] * X(i, first - 1);
      ry[first] -= lower[first] * Y(i, first - 1);
      rx[last] -= upper[last] * X(i, last + 1);
      ry[last] -= upper[last] * Y(i, last + 1);
      for (int j = first + 1; j <= last; ++j) {  // Thomas algorithm
        const double m = lower[j] / diagonal[j - 1];
        diagonal[j] -= m * upper[j - 1];
        rx[j] -= m * rx[j - 1];
        ry[j] -= m * ry[j - 1];
      }
      double nextX = 0, nextY = 0;
      for (int j = last; j >= first; --j) {
        const double xj = (rx[j] - (j < last ? upper[j] * nextX : 0.0)) / diagonal[j];
        const double yj = (ry[j] - (j < last ? upper[j] * nextY : 0.0)) / diagonal[j];
        nextX = xj;
        nextY = yj;
        const double dx = options.relaxation * (xj - o.xAt(i, j));
        const double dy = options.relaxation * (yj - o.yAt(i, j));
        o.xAt(i, j) += dx;
        o.yAt(i, j) += dy;
        largest = std::max(largest, std::hypot(dx, dy));
      }
    }
    for (int j = 0; j < nj; ++j) {  // the seam
      o.xAt(n, j) = o.xAt(0, j);
      o.yAt(n, j) = o.yAt(0, j);
    }
    report.sweeps = sweep;
    report.lastMove = largest / referenceLength;
    if (!std::isfinite(largest)) break;
    if (report.lastMove < options.tolerance) {
      report.converged = true;
      break;
    }
  }
  return report;
}

}  // namespace passageMesh
