#include "passageMesh/mesh/ThompsonSolver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace passageMesh {

namespace {

// The discrete equations at one node, split into what a line solve along j or along i
// needs: the metric coefficients and the cross-derivative terms.
struct NodeTerms {
  double alpha, gamma;     // coefficients of the i- and j-second differences
  double crossX, crossY;   // -2 beta x_xieta, -2 beta y_xieta
  double jacobian;
};

class Grid {
 public:
  Grid(StructuredBlock& block, const GridControl& control)
      : b_(block), n_(block.ni - 1), control_(control) {}

  int n() const { return n_; }
  int east(int i) const { return i + 1 == n_ ? 0 : i + 1; }
  int west(int i) const { return i == 0 ? n_ - 1 : i - 1; }
  double& x(int i, int j) { return b_.xAt(i, j); }
  double& y(int i, int j) { return b_.yAt(i, j); }
  double phi(int i, int j) const { return control_.phi.empty() ? 0.0 : control_.phi[index(i, j)]; }
  double psi(int i, int j) const { return control_.psi.empty() ? 0.0 : control_.psi[index(i, j)]; }
  double forceX(int i, int j) const { return control_.forceX.empty() ? 0.0 : control_.forceX[index(i, j)]; }
  double forceY(int i, int j) const { return control_.forceY.empty() ? 0.0 : control_.forceY[index(i, j)]; }

  NodeTerms terms(int i, int j) const {
    const int e = east(i), w = west(i);
    const double xXi = 0.5 * (b_.xAt(e, j) - b_.xAt(w, j)), yXi = 0.5 * (b_.yAt(e, j) - b_.yAt(w, j));
    const double xEta = 0.5 * (b_.xAt(i, j + 1) - b_.xAt(i, j - 1));
    const double yEta = 0.5 * (b_.yAt(i, j + 1) - b_.yAt(i, j - 1));
    const double xXiEta =
        0.25 * (b_.xAt(e, j + 1) - b_.xAt(e, j - 1) - b_.xAt(w, j + 1) + b_.xAt(w, j - 1));
    const double yXiEta =
        0.25 * (b_.yAt(e, j + 1) - b_.yAt(e, j - 1) - b_.yAt(w, j + 1) + b_.yAt(w, j - 1));
    const double beta = xXi * xEta + yXi * yEta;
    return {xEta * xEta + yEta * yEta, xXi * xXi + yXi * yXi, -2 * beta * xXiEta,
            -2 * beta * yXiEta, xXi * yEta - xEta * yXi};
  }

  // The two residuals at (i, j) and the point-Jacobi scale 2 (alpha + gamma).
  void residual(int i, int j, double& rx, double& ry, double& scale, double& jacobian) const {
    const NodeTerms t = terms(i, j);
    const int e = east(i), w = west(i);
    const double p = phi(i, j), q = psi(i, j);
    auto equation = [&](const std::vector<double>& v, double cross) {
      const double c = v[at(i, j)], vE = v[at(e, j)], vW = v[at(w, j)];
      const double vN = v[at(i, j + 1)], vS = v[at(i, j - 1)];
      return t.alpha * (vE - 2 * c + vW + 0.5 * p * (vE - vW)) +
             t.gamma * (vN - 2 * c + vS + 0.5 * q * (vN - vS)) + cross;
    };
    rx = equation(b_.x, t.crossX) - forceX(i, j);
    ry = equation(b_.y, t.crossY) - forceY(i, j);
    scale = 2 * (t.alpha + t.gamma);
    jacobian = t.jacobian;
  }

 private:
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(i + n_ * j); }
  std::size_t at(int i, int j) const { return static_cast<std::size_t>(i + b_.ni * j); }
  StructuredBlock& b_;
  int n_;
  const GridControl& control_;
};

// Solves the tridiagonal system lower[k] u[k-1] + diagonal[k] u[k] + upper[k] u[k+1] =
// r[k], k in [0, m), for two right-hand sides at once (Thomas algorithm; the arrays are
// overwritten, the solution is left in rx, ry). Diagonally dominant here, no pivoting.
void solveTridiagonal(int m, double* lower, double* diagonal, double* upper, double* rx,
                      double* ry) {
  for (int k = 1; k < m; ++k) {
    const double f = lower[k] / diagonal[k - 1];
    diagonal[k] -= f * upper[k - 1];
    rx[k] -= f * rx[k - 1];
    ry[k] -= f * ry[k - 1];
  }
  rx[m - 1] /= diagonal[m - 1];
  ry[m - 1] /= diagonal[m - 1];
  for (int k = m - 2; k >= 0; --k) {
    rx[k] = (rx[k] - upper[k] * rx[k + 1]) / diagonal[k];
    ry[k] = (ry[k] - upper[k] * ry[k + 1]) / diagonal[k];
  }
}

// The cyclic system (lower[0] couples u[0] to u[m-1], upper[m-1] couples u[m-1] to u[0]),
// by the Sherman-Morrison formula over one extra tridiagonal solve.
void solveCyclicTridiagonal(int m, std::vector<double>& lower, std::vector<double>& diagonal,
                            std::vector<double>& upper, std::vector<double>& rx,
                            std::vector<double>& ry, std::vector<double>& work) {
  const double cornerLow = lower[0], cornerHigh = upper[m - 1];
  const double g = -diagonal[0];
  diagonal[0] -= g;
  diagonal[m - 1] -= cornerHigh * cornerLow / g;
  // u = A'^{-1} [g, 0, ..., cornerHigh]; the same factorisation serves both solves, so
  // solve with three right-hand sides: rx, ry and the correction vector.
  work.assign(static_cast<std::size_t>(m), 0.0);
  work[0] = g;
  work[static_cast<std::size_t>(m - 1)] = cornerHigh;
  for (int k = 1; k < m; ++k) {
    const double f = lower[k] / diagonal[k - 1];
    diagonal[k] -= f * upper[k - 1];
    rx[k] -= f * rx[k - 1];
    ry[k] -= f * ry[k - 1];
    work[k] -= f * work[k - 1];
  }
  for (auto* v : {&rx, &ry, &work}) {
    auto& u = *v;
    u[m - 1] /= diagonal[m - 1];
    for (int k = m - 2; k >= 0; --k) u[k] = (u[k] - upper[k] * u[k + 1]) / diagonal[k];
  }
  const double vCorrection = work[0] + cornerLow / g * work[m - 1];
  const double fx = (rx[0] + cornerLow / g * rx[m - 1]) / (1 + vCorrection);
  const double fy = (ry[0] + cornerLow / g * ry[m - 1]) / (1 + vCorrection);
  for (int k = 0; k < m; ++k) {
    rx[k] -= fx * work[k];
    ry[k] -= fy * work[k];
  }
}

class LineSweeps {
 public:
  LineSweeps(StructuredBlock& block, const GridControl& control, const MovingRows& rows,
             double relaxation)
      : block_(block), grid_(block, control), first_(rows.first()), last_(rows.last(block)),
        omega_(relaxation) {
    const std::size_t size = static_cast<std::size_t>(std::max(block.ni, block.nj));
    for (auto* v : {&lower_, &diagonal_, &upper_, &rx_, &ry_}) v->resize(size);
  }

  // Tridiagonal solves along each j-line, i = 0 .. n-1 in turn.
  void jLines() {
    const int m = last_ - first_ + 1;
    for (int i = 0; i < grid_.n(); ++i) {
      const int e = grid_.east(i), w = grid_.west(i);
      for (int j = first_; j <= last_; ++j) {
        const NodeTerms t = grid_.terms(i, j);
        const double p = grid_.phi(i, j), q = grid_.psi(i, j);
        const int k = j - first_;
        lower_[k] = t.gamma * (1 - 0.5 * q);
        upper_[k] = t.gamma * (1 + 0.5 * q);
        diagonal_[k] = -2 * (t.alpha + t.gamma);
        const double aE = t.alpha * (1 + 0.5 * p), aW = t.alpha * (1 - 0.5 * p);
        rx_[k] = grid_.forceX(i, j) - (aE * grid_.x(e, j) + aW * grid_.x(w, j) + t.crossX);
        ry_[k] = grid_.forceY(i, j) - (aE * grid_.y(e, j) + aW * grid_.y(w, j) + t.crossY);
      }
      rx_[0] -= lower_[0] * grid_.x(i, first_ - 1);
      ry_[0] -= lower_[0] * grid_.y(i, first_ - 1);
      rx_[m - 1] -= upper_[m - 1] * grid_.x(i, last_ + 1);
      ry_[m - 1] -= upper_[m - 1] * grid_.y(i, last_ + 1);
      solveTridiagonal(m, lower_.data(), diagonal_.data(), upper_.data(), rx_.data(), ry_.data());
      for (int j = first_; j <= last_; ++j) {
        grid_.x(i, j) += omega_ * (rx_[j - first_] - grid_.x(i, j));
        grid_.y(i, j) += omega_ * (ry_[j - first_] - grid_.y(i, j));
      }
    }
    copySeam();
  }

  // Cyclic tridiagonal solves around each j = const loop, from the wall outwards.
  void iLines() {
    const int n = grid_.n();
    for (int j = first_; j <= last_; ++j) {
      for (int i = 0; i < n; ++i) {
        const NodeTerms t = grid_.terms(i, j);
        const double p = grid_.phi(i, j), q = grid_.psi(i, j);
        lower_[i] = t.alpha * (1 - 0.5 * p);
        upper_[i] = t.alpha * (1 + 0.5 * p);
        diagonal_[i] = -2 * (t.alpha + t.gamma);
        const double gN = t.gamma * (1 + 0.5 * q), gS = t.gamma * (1 - 0.5 * q);
        rx_[i] = grid_.forceX(i, j) - (gN * grid_.x(i, j + 1) + gS * grid_.x(i, j - 1) + t.crossX);
        ry_[i] = grid_.forceY(i, j) - (gN * grid_.y(i, j + 1) + gS * grid_.y(i, j - 1) + t.crossY);
      }
      solveCyclicTridiagonal(n, lower_, diagonal_, upper_, rx_, ry_, work_);
      for (int i = 0; i < n; ++i) {
        grid_.x(i, j) += omega_ * (rx_[i] - grid_.x(i, j));
        grid_.y(i, j) += omega_ * (ry_[i] - grid_.y(i, j));
      }
    }
    copySeam();
  }

 private:
  void copySeam() {
    const int n = grid_.n();
    for (int j = first_; j <= last_; ++j) {
      block_.xAt(n, j) = block_.xAt(0, j);
      block_.yAt(n, j) = block_.yAt(0, j);
    }
  }

  StructuredBlock& block_;
  Grid grid_;
  int first_, last_;
  double omega_;
  std::vector<double> lower_, diagonal_, upper_, rx_, ry_, work_;
};

void checkSizes(const StructuredBlock& o, const GridControl& control, const MovingRows& rows) {
  const int n = o.ni - 1;
  if (n < 3 || o.nj < 3 || rows.below < 1 || rows.above < 1 || rows.last(o) < rows.first())
    throw std::invalid_argument("solveThompson: block too small for the fixed rows");
  const std::size_t nodes = static_cast<std::size_t>(n) * o.nj;
  auto wrongSize = [nodes](const std::vector<double>& v) { return !v.empty() && v.size() != nodes; };
  if (wrongSize(control.phi) || wrongSize(control.psi) || wrongSize(control.forceX) ||
      wrongSize(control.forceY))
    throw std::invalid_argument("solveThompson: control functions of the wrong size");
}

}  // namespace

void sweepThompson(StructuredBlock& o, const GridControl& control, const MovingRows& rows,
                   double relaxation, bool iLines) {
  checkSizes(o, control, rows);
  LineSweeps sweeps(o, control, rows, relaxation);
  sweeps.jLines();
  if (iLines) sweeps.iLines();
}

void thompsonResidualField(const StructuredBlock& o, const GridControl& control,
                           const MovingRows& rows, std::vector<double>& rx,
                           std::vector<double>& ry) {
  checkSizes(o, control, rows);
  const Grid grid(const_cast<StructuredBlock&>(o), control);
  const std::size_t nodes = static_cast<std::size_t>(grid.n()) * o.nj;
  rx.resize(nodes);
  ry.resize(nodes);
  for (int j = rows.first(); j <= rows.last(o); ++j)
    for (int i = 0; i < grid.n(); ++i) {
      double scale, jacobian;
      const std::size_t k = static_cast<std::size_t>(i + grid.n() * j);
      grid.residual(i, j, rx[k], ry[k], scale, jacobian);
    }
}

double thompsonResidual(const StructuredBlock& o, const GridControl& control,
                        const MovingRows& rows) {
  checkSizes(o, control, rows);
  // Grid takes a mutable block for the sweeps; the residual only reads it.
  const Grid grid(const_cast<StructuredBlock&>(o), control);
  double largest = 0;
  for (int j = rows.first(); j <= rows.last(o); ++j)
    for (int i = 0; i < grid.n(); ++i) {
      double rx, ry, scale, jacobian;
      grid.residual(i, j, rx, ry, scale, jacobian);
      const double r = std::sqrt((rx * rx + ry * ry) / std::abs(jacobian)) / scale;
      if (!(r <= largest)) largest = r;  // also catches NaN
    }
  return largest;
}

ThompsonReport solveThompson(StructuredBlock& o, GridControl& control,
                             const ThompsonOptions& options, const ControlUpdate& update) {
  checkSizes(o, control, options.rows);
  LineSweeps sweeps(o, control, options.rows, options.relaxation);
  return iterateUntilConverged(
      options.maxSweeps, options.tolerance,
      [&] {
        if (update) {
          update(o, control);
          checkSizes(o, control, options.rows);
        }
        sweeps.jLines();
        if (options.iLines) sweeps.iLines();
      },
      [&] { return thompsonResidual(o, control, options.rows); });
}

ThompsonReport iterateUntilConverged(int maxIterations, double tolerance,
                                     const std::function<void()>& iteration,
                                     const std::function<double()>& residual, int stallWindow) {
  ThompsonReport report;
  std::vector<double> history;
  for (int k = 1; k <= maxIterations; ++k) {
    iteration();
    report.sweeps = k;
    report.residual = residual();
    if (!std::isfinite(report.residual)) break;
    if (report.residual <= tolerance) {
      report.converged = true;
      break;
    }
    history.push_back(report.residual);
    if (stallWindow > 0 && k > stallWindow &&
        report.residual > 0.5 * history[static_cast<std::size_t>(k - 1 - stallWindow)])
      break;
  }
  return report;
}

}  // namespace passageMesh
