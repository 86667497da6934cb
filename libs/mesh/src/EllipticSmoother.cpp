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

Eigen::Vector2d nodeAt(const StructuredBlock& o, int i, int j) { return {o.xAt(i, j), o.yAt(i, j)}; }

// The unit normals of row `row`, pointing away from the blade (J = x_xi y_eta - x_eta y_xi
// > 0), per loop node.
std::vector<Eigen::Vector2d> rowNormals(const StructuredBlock& o, int row) {
  const int n = o.ni - 1;
  std::vector<Eigen::Vector2d> normal(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d xXi = nodeAt(o, (i + 1) % n, row) - nodeAt(o, (i + n - 1) % n, row);
    normal[static_cast<std::size_t>(i)] = Eigen::Vector2d(-xXi.y(), xXi.x()).normalized();
  }
  return normal;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The largest angle between a periodic line's target direction and the boundary normal
// (chosen by measurement: docs/elliptic-smoothing.md, sixth session).
constexpr double kMaxTurn = 75 * 3.14159265358979323846 / 180;

// Sorenson's explicit boundary control at row `row` (0: the wall, J: the outer loop): the
// phi, psi that make the equations there hold for lines leaving the boundary along the
// unit directions `direction` (per loop node) with spacing h: x_eta = h direction,
// x_etaeta one-sided from the neighbouring row, x_xieta from the neighbours' x_eta. The
// two equations are solved for phi and psi (a 2 x 2 system with determinant alpha gamma J).
void boundaryControl(const StructuredBlock& o, int i, int row, double h,
                     const std::vector<Eigen::Vector2d>& direction, double& phi, double& psi) {
  const int n = o.ni - 1, e = (i + 1) % n, w = (i + n - 1) % n;
  const int inner = row == 0 ? 1 : row - 1;
  const double side = row == 0 ? 1.0 : -1.0;  // x_inner = x_row + side x_eta + x_etaeta / 2
  const Eigen::Vector2d xXi = 0.5 * (nodeAt(o, e, row) - nodeAt(o, w, row));
  const Eigen::Vector2d xEta = h * direction[static_cast<std::size_t>(i)];
  const Eigen::Vector2d xXiXi = nodeAt(o, e, row) - 2 * nodeAt(o, i, row) + nodeAt(o, w, row);
  const Eigen::Vector2d xEtaEta = 2 * (nodeAt(o, i, inner) - nodeAt(o, i, row) - side * xEta);
  const Eigen::Vector2d xXiEta =
      0.5 * h * (direction[static_cast<std::size_t>(e)] - direction[static_cast<std::size_t>(w)]);
  const double alpha = h * h, beta = xXi.dot(xEta), gamma = xXi.squaredNorm();
  // alpha (x_xixi + phi x_xi) - 2 beta x_xieta + gamma (x_etaeta + psi x_eta) = 0.
  const Eigen::Vector2d r = -(alpha * xXiXi - 2 * beta * xXiEta + gamma * xEtaEta);
  const double jacobian = cross(xXi, xEta);
  phi = cross(r, xEta) / (alpha * jacobian);
  psi = cross(xXi, r) / (gamma * jacobian);
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
  // The periodic segments whose lines continue through the image (none: all square), in
  // the fine grid's loop indices; a loop node i of the grid the values are iterated on is
  // fine node i * loopStep.
  std::optional<PeriodicOuterSegments> periodic;
  double continuationBlend = 0;
  int loopStep = 1;

  Controls(const StructuredBlock& o, const EllipticOptions& options,
           const std::optional<PeriodicOuterSegments>& segments, int step)
      : wallOrthogonal(options.wallOrthogonality),
        outerOrthogonal(options.outerOrthogonality),
        periodic(options.periodicContinuation ? segments : std::nullopt),
        continuationBlend(options.periodicContinuationBlend),
        loopStep(step) {
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

  // The directions the lines should arrive along at the outer loop of `g`: the outer row's
  // normal, and on the periodic segments the chord from the node one row inside to the
  // periodic image of its partner's, turning to the normal next to the corners.
  std::vector<Eigen::Vector2d> outerDirections(const StructuredBlock& g) const {
    const int n = g.ni - 1, J = g.nj - 1;
    std::vector<Eigen::Vector2d> direction = rowNormals(g, J);
    if (!periodic) return direction;
    const PeriodicOuterSegments& p = *periodic;
    const double intervals = p.lowerEnd - p.lowerBegin;
    // Row J - 1 at a fine loop index, linear between this grid's nodes.
    auto innerAt = [&](double fine) {
      const double c = fine / loopStep;
      const int i0 = static_cast<int>(std::floor(c));
      const double f = c - i0;
      return Eigen::Vector2d((1 - f) * nodeAt(g, i0 % n, J - 1) + f * nodeAt(g, (i0 + 1) % n, J - 1));
    };
    for (int i = 0; i < n; ++i) {
      const double fine = static_cast<double>(i) * loopStep;
      const bool lower = fine > p.lowerBegin && fine < p.lowerEnd;
      const bool upper = fine > p.upperBegin && fine < p.upperEnd;
      if (!lower && !upper) continue;
      const Eigen::Vector2d image =
          innerAt(p.lowerBegin + p.upperEnd - fine) + (lower ? -1.0 : 1.0) * p.translation;
      const Eigen::Vector2d through = image - nodeAt(g, i, J - 1);
      Eigen::Vector2d& d = direction[static_cast<std::size_t>(i)];
      // The turn from the normal to the continued line, at most kMaxTurn: a line nearly
      // along the boundary would make the 2 x 2 system near singular. Clipped rather than
      // dropped, so that the target stays continuous while the grid moves (a switch made
      // the iteration cycle between two states).
      const double turn = std::clamp(std::atan2(cross(d, through), d.dot(through)), -kMaxTurn, kMaxTurn);
      const double toCorner = lower ? std::min(fine - p.lowerBegin, p.lowerEnd - fine)
                                    : std::min(fine - p.upperBegin, p.upperEnd - fine);
      const double t = continuationBlend > 0 ? std::min(1.0, toCorner / (continuationBlend * intervals)) : 1.0;
      const double angle = t * t * (3 - 2 * t) * turn;
      d = Eigen::Vector2d(std::cos(angle) * d.x() - std::sin(angle) * d.y(),
                          std::sin(angle) * d.x() + std::cos(angle) * d.y());
    }
    return direction;
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
    const auto outerDirection = c.outerOrthogonal ? c.outerDirections(grid) : std::vector<Eigen::Vector2d>{};
    const auto wallDirection = c.wallOrthogonal ? rowNormals(grid, 0) : std::vector<Eigen::Vector2d>{};
    for (int i = 0; i < n; ++i) {
      double phi, psi;
      const std::size_t k = static_cast<std::size_t>(i);
      auto relaxed = [&](double& value, double target) {
        if (std::isfinite(target)) value = std::clamp(value + relax * (target - value), -limit, limit);
      };
      if (c.outerOrthogonal) {
        boundaryControl(grid, i, grid.nj - 1, c.outerSpacing[k], outerDirection, phi, psi);
        relaxed(c.outerPhi[k], phi);
        relaxed(c.outerPsi[k], psi);
      }
      if (!c.wallOrthogonal) continue;
      boundaryControl(grid, i, 0, c.wallSpacing[k], wallDirection, phi, psi);
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
int outerControlFromCoarseGrid(StructuredBlock& o, Controls& fine, const EllipticOptions& options,
                               const std::optional<PeriodicOuterSegments>& periodic) {
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
  int loopStep = 1;
  for (const Coarsening& c : steps) loopStep *= c.i ? 2 : 1;
  Controls controls(coarsest, options, periodic, loopStep);
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

EllipticReport smoothOBlock(StructuredBlock& o, const EllipticOptions& options,
                            const std::optional<PeriodicOuterSegments>& periodic) {
  if (o.ni - 1 < 3 || o.nj < 4) throw std::invalid_argument("smoothOBlock: block too small");
  Controls controls(o, options, periodic, 1);  // from the algebraic grid, before anything moves
  EllipticReport report;
  if (!options.multigrid) {
    const ThompsonReport r =
        solveWithOuterControl(o, controls, options, options.maxSweeps, options.tolerance);
    return {r.sweeps, 0, r.residual, r.converged};
  }
  report.controlSweeps = outerControlFromCoarseGrid(o, controls, options, periodic);
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
