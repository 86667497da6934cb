#include "passageMesh/mesh/EllipticSmoother.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "passageMesh/mesh/GridCoarsening.hpp"
#include "passageMesh/mesh/ThompsonMultigrid.hpp"

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

// The control functions of one grid: what comes from its initial (algebraic) nodes, and
// the outer control values.
struct Controls {
  std::vector<double> wallPhi;       // per i
  std::vector<double> linePsi;       // per node i + n j
  std::vector<double> outerSpacing;  // per i: the initial spacing at the outer loop
  std::vector<double> outerPhi, outerPsi;

  explicit Controls(const StructuredBlock& o) {
    const int n = o.ni - 1, J = o.nj - 1;
    wallPhi = loopDistributionControl(o, 0);
    linePsi.assign(static_cast<std::size_t>(n) * o.nj, 0.0);
    for (int i = 0; i < n; ++i)
      for (int j = 1; j < J; ++j)
        linePsi[static_cast<std::size_t>(i + n * j)] =
            distributionControl(distance(o, i, j - 1, i, j), distance(o, i, j, i, j + 1));
    outerPhi = loopDistributionControl(o, J);
    outerPsi.resize(static_cast<std::size_t>(n));
    outerSpacing.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      outerSpacing[static_cast<std::size_t>(i)] = distance(o, i, J - 1, i, J);
      outerPsi[static_cast<std::size_t>(i)] = linePsi[static_cast<std::size_t>(i + n * (J - 1))];
    }
  }

  // The blend of the header into `g` for a grid of nj rows.
  void blendInto(GridControl& g, int nj) const {
    const int n = static_cast<int>(wallPhi.size()), J = nj - 1;
    g.phi.assign(linePsi.size(), 0.0);
    g.psi.assign(linePsi.size(), 0.0);
    for (int j = 1; j < J; ++j) {
      const double s = static_cast<double>(j - 1) / (J - 1);
      const double a = (1 - s) * (1 - s) * (1 - s), b = s * s * s;
      for (int i = 0; i < n; ++i) {
        const std::size_t k = static_cast<std::size_t>(i + n * j), ki = static_cast<std::size_t>(i);
        g.phi[k] = a * wallPhi[ki] + b * outerPhi[ki];
        g.psi[k] = linePsi[k] + b * (outerPsi[ki] - linePsi[static_cast<std::size_t>(i + n * (J - 1))]);
      }
    }
  }
};

// Moves the outer control values `relax` of the way to what the grid asks for, and blends.
ControlUpdate outerControlUpdate(Controls& c, double relax, double limit) {
  return [&c, relax, limit](const StructuredBlock& grid, GridControl& g) {
    const int n = grid.ni - 1;
    for (int i = 0; i < n; ++i) {
      double phi, psi;
      const std::size_t k = static_cast<std::size_t>(i);
      outerControl(grid, i, c.outerSpacing[k], phi, psi);
      if (std::isfinite(phi)) c.outerPhi[k] = std::clamp(c.outerPhi[k] + relax * (phi - c.outerPhi[k]), -limit, limit);
      if (std::isfinite(psi)) c.outerPsi[k] = std::clamp(c.outerPsi[k] + relax * (psi - c.outerPsi[k]), -limit, limit);
    }
    c.blendInto(g, grid.nj);
  };
}

// Fixed below: the wall, the first row and the rest of the wall layer; above: the outer
// loop.
MovingRows movingRows(const StructuredBlock& o, const EllipticOptions& options) {
  MovingRows rows;
  rows.below = 1 + std::clamp(o.nj / options.wallLayerFraction, 1, options.wallLayerRows);
  rows.above = 1;
  return rows;
}

// Solves `o` and its outer control values together by single-grid sweeps.
ThompsonReport solveWithOuterControl(StructuredBlock& o, Controls& c, const EllipticOptions& options,
                                     int maxSweeps, double tolerance) {
  const auto update = outerControlUpdate(c, options.controlRelaxation, options.controlLimit);
  GridControl control;
  ThompsonOptions single;
  single.maxSweeps = maxSweeps;
  single.tolerance = tolerance;
  single.relaxation = options.lineRelaxation;
  single.rows = movingRows(o, options);
  return solveThompson(o, control, single, update);
}

// Finds the outer control values on a coarse copy of `o` and returns them for `o`'s loop;
// moves `o`'s nodes by the coarse solve's displacement (a start for the full solve).
int outerControlFromCoarseGrid(StructuredBlock& o, Controls& fine, const EllipticOptions& options) {
  std::vector<StructuredBlock> initial{o};
  std::vector<Coarsening> steps;
  while (initial.back().ni - 1 > options.controlGridLoop) {
    // Around the loop only: psi, the spacing control along the lines, does not carry
    // over between grids with other rows (measured: the first cells then grew 4-fold).
    const Coarsening c = coarseningOf(initial.back(), movingRows(o, options), 8, 1 << 30);
    if (!c.any()) break;
    steps.push_back(c);
    initial.push_back(coarseBlock(initial.back(), c));
  }
  StructuredBlock coarsest = initial.back();
  Controls controls(coarsest);
  const ThompsonReport r = solveWithOuterControl(coarsest, controls, options,
                                                 options.controlMaxSweeps, options.controlTolerance);
  if (!std::isfinite(r.residual)) return r.sweeps;
  // Back up the levels: displacement and outer control values, halved per coarsened
  // direction (they are per index step).
  StructuredBlock solved = coarsest;
  std::vector<double> phi = controls.outerPhi, psi = controls.outerPsi, dx, dy;
  for (std::size_t l = steps.size(); l-- > 0;) {
    StructuredBlock finer = initial[l];
    interpolateDisplacement(initial[l + 1], solved, steps[l], finer, movingRows(o, options), dx, dy);
    for (std::size_t k = 0; k < finer.x.size(); ++k) {
      finer.x[k] += dx[k];
      finer.y[k] += dy[k];
    }
    phi = interpolateAroundLoop(phi, steps[l], finer.ni - 1);
    psi = interpolateAroundLoop(psi, steps[l], finer.ni - 1);
    for (auto& v : phi) v *= steps[l].i ? 0.5 : 1.0;
    for (auto& v : psi) v *= steps[l].j ? 0.5 : 1.0;
    solved = std::move(finer);
  }
  o = solved;
  fine.outerPhi = phi;
  fine.outerPsi = psi;
  return r.sweeps;
}

}  // namespace

EllipticReport smoothOBlock(StructuredBlock& o, const EllipticOptions& options) {
  if (o.ni - 1 < 3 || o.nj < 4) throw std::invalid_argument("smoothOBlock: block too small");
  Controls controls(o);  // from the algebraic grid, before anything moves
  EllipticReport report;
  if (!options.multigrid) {
    const ThompsonReport r =
        solveWithOuterControl(o, controls, options, options.maxSweeps, options.tolerance);
    return {r.sweeps, 0, r.residual, r.converged};
  }
  report.controlSweeps = outerControlFromCoarseGrid(o, controls, options);
  GridControl control;
  controls.blendInto(control, o.nj);
  MultigridOptions mg;
  mg.tolerance = options.tolerance;
  mg.maxCycles = options.maxCycles;
  mg.rows = movingRows(o, options);
  const MultigridReport r = solveThompsonMultigrid(o, control, mg);
  report.iterations = r.cycles;
  report.residual = r.residual;
  report.converged = r.converged;
  return report;
}

}  // namespace passageMesh
