#include "passageMesh/mesh/EllipticSmoother.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
  // the fine grid's loop indices; loop node i of the grid the values are iterated on is
  // fine node fineIndex[i] (i = 0 .. n; empty: the fine grid itself).
  std::optional<PeriodicOuterSegments> periodic;
  double continuationBlend = 0;
  std::vector<double> fineIndex;

  Controls(const StructuredBlock& o, const EllipticOptions& options,
           const std::optional<PeriodicOuterSegments>& segments, std::vector<double> fineIndices)
      : wallOrthogonal(options.wallOrthogonality),
        outerOrthogonal(options.outerOrthogonality),
        periodic(options.periodicContinuation ? segments : std::nullopt),
        continuationBlend(options.periodicContinuationBlend),
        fineIndex(std::move(fineIndices)) {
    if (fineIndex.empty())
      for (int i = 0; i < o.ni; ++i) fineIndex.push_back(i);
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
      const int i0 = std::clamp(static_cast<int>(std::upper_bound(fineIndex.begin(), fineIndex.end(), fine) -
                                                 fineIndex.begin()) - 1, 0, n - 1);
      const double f = (fine - fineIndex[static_cast<std::size_t>(i0)]) /
                       (fineIndex[static_cast<std::size_t>(i0 + 1)] - fineIndex[static_cast<std::size_t>(i0)]);
      return Eigen::Vector2d((1 - f) * nodeAt(g, i0, J - 1) + f * nodeAt(g, (i0 + 1) % n, J - 1));
    };
    for (int i = 0; i < n; ++i) {
      const double fine = fineIndex[static_cast<std::size_t>(i)];
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

// The fine loop index t of each node I = 0 .. nc of the control grid: evenly spaced,
// t = I n / nc, and where a leading edge is given (fine loop node `leadingEdge` > 0) bent
// smoothly so that it is a node too: t = I n / nc + d sin^2(pi I / nc) / sin^2(pi L / nc),
// with L its nearest control node and d the shift that puts L on it (at most half an
// interval). The trailing edge (t = 0, the seam) stays a node with the slope the same on
// both sides, so that the grid is symmetric about it.
std::vector<double> controlGridIndices(int n, int nc, int leadingEdge) {
  const double r = static_cast<double>(n) / nc;
  const int L = static_cast<int>(std::lround(leadingEdge / r));
  const bool bend = leadingEdge > 0 && L > 0 && L < nc;
  const double pi = 3.14159265358979323846;
  const double d = bend ? leadingEdge - r * L : 0.0, norm = bend ? std::pow(std::sin(pi * L / nc), 2) : 1.0;
  std::vector<double> t(static_cast<std::size_t>(nc + 1));
  for (int I = 0; I <= nc; ++I) t[static_cast<std::size_t>(I)] = r * I + d * std::pow(std::sin(pi * I / nc), 2) / norm;
  if (bend) t[static_cast<std::size_t>(L)] = leadingEdge;  // exactly, not to rounding
  t.front() = 0;
  t.back() = n;
  return t;
}

// `o` resampled around the loop at the fine loop indices t (increasing, t[0] = 0, the last
// n: the seam), each row's node linear between the fine nodes either side of t.
StructuredBlock resampledAroundLoop(const StructuredBlock& o, const std::vector<double>& t) {
  const int n = o.ni - 1;
  StructuredBlock c = o;
  c.ni = static_cast<int>(t.size());
  c.x.assign(static_cast<std::size_t>(c.ni) * o.nj, 0.0);
  c.y.assign(c.x.size(), 0.0);
  for (int j = 0; j < o.nj; ++j)
    for (int I = 0; I < c.ni; ++I) {
      const int i0 = std::min(static_cast<int>(t[static_cast<std::size_t>(I)]), n - 1);
      const double f = t[static_cast<std::size_t>(I)] - i0;
      c.xAt(I, j) = (1 - f) * o.xAt(i0, j) + f * o.xAt(i0 + 1, j);
      c.yAt(I, j) = (1 - f) * o.yAt(i0, j) + f * o.yAt(i0 + 1, j);
    }
  return c;
}

// A per-node value of the control grid's loop (t.size() - 1 values) at the fine loop's n
// nodes, linear in t.
std::vector<double> fromControlGrid(const std::vector<double>& coarse, const std::vector<double>& t, int n) {
  const int nc = static_cast<int>(coarse.size());
  std::vector<double> fine(static_cast<std::size_t>(n));
  std::size_t I = 0;
  for (int i = 0; i < n; ++i) {
    while (I + 1 < t.size() - 1 && t[I + 1] <= i) ++I;
    const double f = (i - t[I]) / (t[I + 1] - t[I]);
    fine[static_cast<std::size_t>(i)] =
        (1 - f) * coarse[I] + f * coarse[(I + 1) % static_cast<std::size_t>(nc)];
  }
  return fine;
}

// Finds the outer (and wall) control values on a copy of `o` resampled around the loop at
// at most options.controlGridLoop nodes, the blade's edges among them (all rows kept: psi,
// the spacing control along the lines, does not carry over between grids with other rows;
// measured: the first cells then grew 4-fold), and returns them for `o`'s loop; moves
// `o`'s nodes by the coarse solve's displacement (a start for the full solve).
// The control grid used to take every other fine node, repeatedly: an odd loop then had a
// single-interval step, and which nodes next to a sharp edge the coarse grid held changed
// with n mod 8 (docs/elliptic-smoothing.md, "A control grid resampled in the loop index").
int outerControlFromCoarseGrid(StructuredBlock& o, Controls& fine, const EllipticOptions& options,
                               const std::optional<PeriodicOuterSegments>& periodic, int leadingEdge) {
  const int n = o.ni - 1;
  const std::vector<double> t = controlGridIndices(n, std::min(n, options.controlGridLoop), leadingEdge);
  const int nc = static_cast<int>(t.size()) - 1;
  const StructuredBlock initial = resampledAroundLoop(o, t);
  StructuredBlock coarse = initial;
  Controls controls(coarse, options, periodic, t);
  const ThompsonReport r = solveWithOuterControl(coarse, controls, options,
                                                 options.controlMaxSweeps, options.controlTolerance);
  if (!std::isfinite(r.residual)) return r.sweeps;
  // The displacement, and the boundary control values. psi is per row and carries over
  // as it is; phi is per loop index step: phi_fine = phi / t' + t'' / t'^2 at the control
  // grid's nodes (t' and t'' of the index map).
  const MovingRows rows = movingRows(o, options);
  std::vector<double> dx(static_cast<std::size_t>(nc)), dy(dx.size());
  for (int j = rows.first(); j <= rows.last(o); ++j) {
    for (int I = 0; I < nc; ++I) {
      dx[static_cast<std::size_t>(I)] = coarse.xAt(I, j) - initial.xAt(I, j);
      dy[static_cast<std::size_t>(I)] = coarse.yAt(I, j) - initial.yAt(I, j);
    }
    const std::vector<double> fx = fromControlGrid(dx, t, n), fy = fromControlGrid(dy, t, n);
    for (int i = 0; i < n; ++i) {
      o.xAt(i, j) += fx[static_cast<std::size_t>(i)];
      o.yAt(i, j) += fy[static_cast<std::size_t>(i)];
    }
    o.xAt(n, j) = o.xAt(0, j);
    o.yAt(n, j) = o.yAt(0, j);
  }
  auto phiToFine = [&](std::vector<double> phi) {
    for (int I = 0; I < nc; ++I) {
      const double before = I > 0 ? t[static_cast<std::size_t>(I - 1)] : t[static_cast<std::size_t>(nc - 1)] - n;
      const double at = t[static_cast<std::size_t>(I)], after = t[static_cast<std::size_t>(I + 1)];
      const double slope = 0.5 * (after - before), second = after - 2 * at + before;
      phi[static_cast<std::size_t>(I)] = phi[static_cast<std::size_t>(I)] / slope + second / (slope * slope);
    }
    return fromControlGrid(phi, t, n);
  };
  fine.outerPhi = phiToFine(controls.outerPhi);
  fine.outerPsi = fromControlGrid(controls.outerPsi, t, n);
  if (fine.wallOrthogonal) {
    fine.wallPhi = phiToFine(controls.wallPhi);
    fine.wallPsi = fromControlGrid(controls.wallPsi, t, n);
  }
  return r.sweeps;
}

}  // namespace

EllipticReport smoothOBlock(StructuredBlock& o, const EllipticOptions& options,
                            const std::optional<PeriodicOuterSegments>& periodic, int leadingEdge) {
  if (o.ni - 1 < 3 || o.nj < 4) throw std::invalid_argument("smoothOBlock: block too small");
  Controls controls(o, options, periodic, {});  // from the algebraic grid, before anything moves
  EllipticReport report;
  if (!options.multigrid) {
    const ThompsonReport r =
        solveWithOuterControl(o, controls, options, options.maxSweeps, options.tolerance);
    return {r.sweeps, 0, r.residual, r.converged};
  }
  report.controlSweeps = outerControlFromCoarseGrid(o, controls, options, periodic, leadingEdge);
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
