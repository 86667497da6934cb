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

// Sorenson's explicit boundary control at row `row` (0: the wall, J: the outer loop): the
// phi, psi that make the equations there hold for lines leaving the boundary orthogonally
// with spacing h (x_eta prescribed, x_etaeta one-sided from the neighbouring row).
void boundaryControl(const StructuredBlock& o, int i, int row, double h, double& phi, double& psi) {
  const int n = o.ni - 1, e = (i + 1) % n, w = (i + n - 1) % n;
  const int inner = row == 0 ? 1 : row - 1;
  const double side = row == 0 ? 1.0 : -1.0;  // x_inner = x_row + side x_eta + x_etaeta / 2
  const double xXi = 0.5 * (o.xAt(e, row) - o.xAt(w, row)), yXi = 0.5 * (o.yAt(e, row) - o.yAt(w, row));
  const double gamma = xXi * xXi + yXi * yXi, alpha = h * h, length = std::sqrt(gamma);
  // x_eta points away from the blade: J = x_xi y_eta - x_eta y_xi > 0.
  const double xEta = -h * yXi / length, yEta = h * xXi / length;
  const double xXiXi = o.xAt(e, row) - 2 * o.xAt(i, row) + o.xAt(w, row);
  const double yXiXi = o.yAt(e, row) - 2 * o.yAt(i, row) + o.yAt(w, row);
  const double xEtaEta = 2 * (o.xAt(i, inner) - o.xAt(i, row) - side * xEta);
  const double yEtaEta = 2 * (o.yAt(i, inner) - o.yAt(i, row) - side * yEta);
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
  // With wall orthogonality: Sorenson's values at the wall, blended like the outer ones.
  bool wallOrthogonal = false;
  std::vector<double> wallSpacing, wallPsi;
  // Without outer orthogonality the outer values are zero and stay so (no pull on the
  // lines at the outer loop: they arrive at the angle the interior gives them).
  bool outerOrthogonal = true;

  Controls(const StructuredBlock& o, bool orthogonalWall, bool orthogonalOuter)
      : wallOrthogonal(orthogonalWall), outerOrthogonal(orthogonalOuter) {
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
    if (!outerOrthogonal) {
      outerPhi.assign(outerPhi.size(), 0.0);
      outerPsi.assign(outerPsi.size(), 0.0);
    }
    if (wallOrthogonal) {
      wallSpacing.resize(static_cast<std::size_t>(n));
      wallPsi.resize(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) {
        wallSpacing[static_cast<std::size_t>(i)] = distance(o, i, 0, i, 1);
        wallPsi[static_cast<std::size_t>(i)] = linePsi[static_cast<std::size_t>(i + n)];
      }
    }
  }

  // The blend of the header into `g` for a grid of nj rows.
  void blendInto(GridControl& g, int nj) const {
    const int n = static_cast<int>(wallPhi.size()), J = nj - 1;
    g.phi.assign(linePsi.size(), 0.0);
    g.psi.assign(linePsi.size(), 0.0);
    for (int j = 1; j < J; ++j) {
      const double s = wallOrthogonal ? static_cast<double>(j) / J : static_cast<double>(j - 1) / (J - 1);
      const double a = (1 - s) * (1 - s) * (1 - s), b = s * s * s;
      for (int i = 0; i < n; ++i) {
        const std::size_t k = static_cast<std::size_t>(i + n * j), ki = static_cast<std::size_t>(i);
        g.phi[k] = a * wallPhi[ki] + b * outerPhi[ki];
        g.psi[k] = linePsi[k] + b * (outerPsi[ki] - linePsi[static_cast<std::size_t>(i + n * (J - 1))]);
        if (wallOrthogonal) g.psi[k] += a * (wallPsi[ki] - linePsi[static_cast<std::size_t>(i + n)]);
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
      auto relaxed = [&](double& value, double target) {
        if (std::isfinite(target)) value = std::clamp(value + relax * (target - value), -limit, limit);
      };
      if (c.outerOrthogonal) {
        boundaryControl(grid, i, grid.nj - 1, c.outerSpacing[k], phi, psi);
        relaxed(c.outerPhi[k], phi);
        relaxed(c.outerPsi[k], psi);
      }
      if (!c.wallOrthogonal) continue;
      boundaryControl(grid, i, 0, c.wallSpacing[k], phi, psi);
      relaxed(c.wallPhi[k], phi);
      relaxed(c.wallPsi[k], psi);
    }
    c.blendInto(g, grid.nj);
  };
}

// Fixed below: the wall, the first row and the rest of the wall layer; above: the outer
// loop.
MovingRows movingRows(const StructuredBlock& o, const EllipticOptions& options) {
  MovingRows rows;
  rows.below = 1 + std::min(options.wallLayerRows, std::max(1, o.nj / options.wallLayerFraction));
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
  Controls controls(coarsest, options.wallOrthogonality, options.outerOrthogonality);
  const ThompsonReport r = solveWithOuterControl(coarsest, controls, options,
                                                 options.controlMaxSweeps, options.controlTolerance);
  if (!std::isfinite(r.residual)) return r.sweeps;
  // Back up the levels: displacement and outer control values, halved per coarsened
  // direction (they are per index step).
  StructuredBlock solved = coarsest;
  std::vector<double> dx, dy;
  // The boundary values carried up, each with whether it is a phi (per i step) or a psi.
  std::vector<std::pair<std::vector<double>*, bool>> carried{{&controls.outerPhi, true},
                                                             {&controls.outerPsi, false}};
  if (controls.wallOrthogonal) {
    carried.emplace_back(&controls.wallPhi, true);
    carried.emplace_back(&controls.wallPsi, false);
  }
  for (std::size_t l = steps.size(); l-- > 0;) {
    StructuredBlock finer = initial[l];
    interpolateDisplacement(initial[l + 1], solved, steps[l], finer, movingRows(o, options), dx, dy);
    for (std::size_t k = 0; k < finer.x.size(); ++k) {
      finer.x[k] += dx[k];
      finer.y[k] += dy[k];
    }
    for (auto& [values, isPhi] : carried) {
      *values = interpolateAroundLoop(*values, steps[l], finer.ni - 1);
      const bool halve = isPhi ? steps[l].i : steps[l].j;
      for (auto& v : *values) v *= halve ? 0.5 : 1.0;
    }
    solved = std::move(finer);
  }
  o = solved;
  fine.outerPhi = controls.outerPhi;
  fine.outerPsi = controls.outerPsi;
  if (fine.wallOrthogonal) {
    fine.wallPhi = controls.wallPhi;
    fine.wallPsi = controls.wallPsi;
  }
  return r.sweeps;
}

}  // namespace

EllipticReport smoothOBlock(StructuredBlock& o, const EllipticOptions& options) {
  if (o.ni - 1 < 3 || o.nj < 4) throw std::invalid_argument("smoothOBlock: block too small");
  Controls controls(o, options.wallOrthogonality, options.outerOrthogonality);  // from the algebraic grid, before anything moves
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
