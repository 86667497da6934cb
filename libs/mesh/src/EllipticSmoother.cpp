#include "passageMesh/mesh/EllipticSmoother.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace passageMesh {

namespace {

double distance(const StructuredBlock& o, int i0, int j0, int i1, int j1) {
  return std::hypot(o.xAt(i1, j1) - o.xAt(i0, j0), o.yAt(i1, j1) - o.yAt(i0, j0));
}

// -2 (a - b) / (a + b) for the spacings b before and a after a node: the discrete
// -s'' / s' that reproduces the distribution.
double distributionControl(double before, double after) {
  return -2 * (after - before) / (after + before);
}

// phi = -t_xixi / t_xi of the node distribution around the loop j = const.
std::vector<double> loopDistributionControl(const StructuredBlock& o, int j) {
  const int n = o.ni - 1;
  std::vector<double> phi(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    phi[static_cast<std::size_t>(i)] = distributionControl(
        distance(o, (i + n - 1) % n, j, i, j), distance(o, i, j, (i + 1) % n, j));
  return phi;
}

// Sorenson's explicit boundary control at the outer row: the phi, psi that make the
// equations at (i, J) hold for lines leaving the outer loop orthogonally with spacing h
// (x_eta prescribed, x_etaeta from the row inside, one-sided).
void outerControl(const StructuredBlock& o, int i, double h, double& phi, double& psi) {
  const int n = o.ni - 1, J = o.nj - 1, e = (i + 1) % n, w = (i + n - 1) % n;
  const double xXi = 0.5 * (o.xAt(e, J) - o.xAt(w, J)), yXi = 0.5 * (o.yAt(e, J) - o.yAt(w, J));
  const double gamma = xXi * xXi + yXi * yXi, alpha = h * h, length = std::sqrt(gamma);
  // x_eta points away from the blade: J = x_xi y_eta - x_eta y_xi > 0.
  const double xEta = -h * yXi / length, yEta = h * xXi / length;
  const double xXiXi = o.xAt(e, J) - 2 * o.xAt(i, J) + o.xAt(w, J);
  const double yXiXi = o.yAt(e, J) - 2 * o.yAt(i, J) + o.yAt(w, J);
  // x_{J-1} = x_J - x_eta + x_etaeta / 2
  const double xEtaEta = 2 * (o.xAt(i, J - 1) - o.xAt(i, J) + xEta);
  const double yEtaEta = 2 * (o.yAt(i, J - 1) - o.yAt(i, J) + yEta);
  // x_xi and x_eta are orthogonal (beta = 0, x_xieta drops out): the equation
  // alpha (x_xixi + phi x_xi) + gamma (x_etaeta + psi x_eta) = 0 projected on each.
  phi = -(xXiXi * xXi + yXiXi * yXi) / gamma - (xEtaEta * xXi + yEtaEta * yXi) / alpha;
  psi = -(xXiXi * xEta + yXiXi * yEta) / gamma - (xEtaEta * xEta + yEtaEta * yEta) / alpha;
}

}  // namespace

EllipticReport smoothOBlock(StructuredBlock& o, const EllipticOptions& options) {
  const int n = o.ni - 1, nj = o.nj, J = nj - 1;
  if (n < 3 || nj < 4) throw std::invalid_argument("smoothOBlock: block too small");
  auto at = [n](int i, int j) { return static_cast<std::size_t>(i + n * j); };
  auto node = [](int i) { return static_cast<std::size_t>(i); };

  const auto wallPhi = loopDistributionControl(o, 0);
  std::vector<double> linePsi(static_cast<std::size_t>(n) * nj, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 1; j < J; ++j)
      linePsi[at(i, j)] = distributionControl(distance(o, i, j - 1, i, j), distance(o, i, j, i, j + 1));
  std::vector<double> outerPhi = loopDistributionControl(o, J), outerPsi(node(n)), outerSpacing(node(n));
  for (int i = 0; i < n; ++i) {
    outerSpacing[node(i)] = distance(o, i, J - 1, i, J);
    outerPsi[node(i)] = linePsi[at(i, J - 1)];
  }
  std::vector<double> wallWeight(node(nj)), outerWeight(node(nj));
  for (int j = 1; j < nj; ++j) {
    const double s = static_cast<double>(j - 1) / (J - 1);
    wallWeight[node(j)] = (1 - s) * (1 - s) * (1 - s);
    outerWeight[node(j)] = s * s * s;
  }

  const double limit = options.controlLimit, relax = options.controlRelaxation;
  auto update = [&](const StructuredBlock& grid, GridControl& c) {
    for (int i = 0; i < n; ++i) {
      double phi, psi;
      outerControl(grid, i, outerSpacing[node(i)], phi, psi);
      auto& p = outerPhi[node(i)];
      auto& q = outerPsi[node(i)];
      if (std::isfinite(phi)) p = std::clamp(p + relax * (phi - p), -limit, limit);
      if (std::isfinite(psi)) q = std::clamp(q + relax * (psi - q), -limit, limit);
    }
    for (int j = 1; j < nj; ++j) {
      const double a = wallWeight[node(j)], b = outerWeight[node(j)];
      for (int i = 0; i < n; ++i) {
        c.phi[at(i, j)] = a * wallPhi[node(i)] + b * outerPhi[node(i)];
        c.psi[at(i, j)] = linePsi[at(i, j)] + b * (outerPsi[node(i)] - linePsi[at(i, J - 1)]);
      }
    }
  };
  GridControl control;
  control.phi.assign(linePsi.size(), 0.0);
  control.psi.assign(linePsi.size(), 0.0);
  ThompsonOptions thompson;
  thompson.maxSweeps = options.maxSweeps;
  thompson.tolerance = options.tolerance;
  thompson.relaxation = options.lineRelaxation;
  thompson.fixedRows = 2;
  const ThompsonReport r = solveThompson(o, control, thompson, update);
  return {r.sweeps, r.residual, r.converged};
}

}  // namespace passageMesh
