#include "passageMesh/mesh/ThompsonSolver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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

// The line solves below assemble each node's coefficients and eliminate it in the same
// loop (Thomas algorithm, forward elimination with the reciprocal of the pivot kept, then
// back substitution): the elimination is a chain of dependent divisions, and assembling
// the next node's coefficients in the same loop gives the processor independent work to
// overlap with it. Diagonally dominant here, no pivoting.
class LineSweeps {
 public:
  LineSweeps(StructuredBlock& block, const GridControl& control, const MovingRows& rows,
             double relaxation)
      : block_(block), grid_(block, control), first_(rows.first()), last_(rows.last(block)),
        omega_(relaxation) {
    const std::size_t size = static_cast<std::size_t>(std::max(block.ni, block.nj));
    for (auto* v : {&pivotUpper_, &solutionX_, &solutionY_, &correction_}) v->resize(size);
  }

  // Tridiagonal solves along each j-line, i = 0 .. n-1 in turn.
  void jLines() {
    const int m = last_ - first_ + 1;
    for (int i = 0; i < grid_.n(); ++i) {
      const int e = grid_.east(i), w = grid_.west(i);
      double previousX = 0, previousY = 0, previousUpper = 0;
      for (int k = 0; k < m; ++k) {
        const int j = first_ + k;
        const NodeTerms t = grid_.terms(i, j);
        const double p = grid_.phi(i, j), q = grid_.psi(i, j);
        const double lower = t.gamma * (1 - 0.5 * q), upper = t.gamma * (1 + 0.5 * q);
        const double aE = t.alpha * (1 + 0.5 * p), aW = t.alpha * (1 - 0.5 * p);
        double rx = grid_.forceX(i, j) - (aE * grid_.x(e, j) + aW * grid_.x(w, j) + t.crossX);
        double ry = grid_.forceY(i, j) - (aE * grid_.y(e, j) + aW * grid_.y(w, j) + t.crossY);
        if (k == 0) {
          rx -= lower * grid_.x(i, first_ - 1);
          ry -= lower * grid_.y(i, first_ - 1);
        }
        if (k == m - 1) {
          rx -= upper * grid_.x(i, last_ + 1);
          ry -= upper * grid_.y(i, last_ + 1);
        }
        const double pivot = 1 / (-2 * (t.alpha + t.gamma) - lower * previousUpper);
        previousUpper = pivotUpper_[k] = upper * pivot;
        previousX = solutionX_[k] = (rx - lower * previousX) * pivot;
        previousY = solutionY_[k] = (ry - lower * previousY) * pivot;
      }
      backSubstitute(m);
      for (int k = 0; k < m; ++k) {
        grid_.x(i, first_ + k) += omega_ * (solutionX_[k] - grid_.x(i, first_ + k));
        grid_.y(i, first_ + k) += omega_ * (solutionY_[k] - grid_.y(i, first_ + k));
      }
    }
    copySeam();
  }

  // Cyclic tridiagonal solves around each j = const loop, from the wall outwards: the
  // Sherman-Morrison formula over the tridiagonal system with the corner couplings
  // (node 0 to node n-1 and back) taken out, solved for a third right-hand side, the
  // correction vector, with the same elimination.
  void iLines() {
    const int n = grid_.n();
    for (int j = first_; j <= last_; ++j) {
      double previousX = 0, previousY = 0, previousCorrection = 0, previousUpper = 0;
      double cornerLow = 0, g = 0;
      for (int i = 0; i < n; ++i) {
        const NodeTerms t = grid_.terms(i, j);
        const double p = grid_.phi(i, j), q = grid_.psi(i, j);
        const double lower = t.alpha * (1 - 0.5 * p), upper = t.alpha * (1 + 0.5 * p);
        double diagonal = -2 * (t.alpha + t.gamma);
        const double gN = t.gamma * (1 + 0.5 * q), gS = t.gamma * (1 - 0.5 * q);
        const double rx = grid_.forceX(i, j) - (gN * grid_.x(i, j + 1) + gS * grid_.x(i, j - 1) + t.crossX);
        const double ry = grid_.forceY(i, j) - (gN * grid_.y(i, j + 1) + gS * grid_.y(i, j - 1) + t.crossY);
        double correction = 0;
        if (i == 0) {
          cornerLow = lower;
          g = -diagonal;
          diagonal -= g;
          correction = g;
        }
        if (i == n - 1) {  // upper is the corner coupling to node 0
          diagonal -= upper * cornerLow / g;
          correction = upper;
        }
        // (at i = 0 the previous values are 0: cornerLow couples through the correction)
        const double pivot = 1 / (diagonal - lower * previousUpper);
        previousUpper = pivotUpper_[i] = upper * pivot;
        previousX = solutionX_[i] = (rx - lower * previousX) * pivot;
        previousY = solutionY_[i] = (ry - lower * previousY) * pivot;
        previousCorrection = correction_[i] = (correction - lower * previousCorrection) * pivot;
      }
      backSubstitute(n, true);
      const double vCorrection = correction_[0] + cornerLow / g * correction_[n - 1];
      const double fx = (solutionX_[0] + cornerLow / g * solutionX_[n - 1]) / (1 + vCorrection);
      const double fy = (solutionY_[0] + cornerLow / g * solutionY_[n - 1]) / (1 + vCorrection);
      for (int i = 0; i < n; ++i) {
        grid_.x(i, j) += omega_ * (solutionX_[i] - fx * correction_[i] - grid_.x(i, j));
        grid_.y(i, j) += omega_ * (solutionY_[i] - fy * correction_[i] - grid_.y(i, j));
      }
    }
    copySeam();
  }

 private:
  // The value just found is carried to the next node in a register: reloaded from the
  // vector, each node waited for the store of the one before (a quarter of a sweep's time).
  void backSubstitute(int m, bool withCorrection = false) {
    double nextX = solutionX_[m - 1], nextY = solutionY_[m - 1], nextCorrection = correction_[m - 1];
    for (int k = m - 2; k >= 0; --k) {
      const double upper = pivotUpper_[k];
      solutionX_[k] = nextX = solutionX_[k] - upper * nextX;
      solutionY_[k] = nextY = solutionY_[k] - upper * nextY;
      if (withCorrection) correction_[k] = nextCorrection = correction_[k] - upper * nextCorrection;
    }
  }

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
  // Per node of the line: upper / pivot, then the solutions (x, y and the correction).
  std::vector<double> pivotUpper_, solutionX_, solutionY_, correction_;
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
  // The measure's division and square root only where a node may beat the largest so far:
  // r^2 = a / b with a = rx^2 + ry^2, b = |J| scale^2, tested against the largest with a
  // margin far above rounding, so the result is the exact measure's, bit for bit.
  double largest = 0, threshold = 0;
  for (int j = rows.first(); j <= rows.last(o); ++j)
    for (int i = 0; i < grid.n(); ++i) {
      double rx, ry, scale, jacobian;
      grid.residual(i, j, rx, ry, scale, jacobian);
      const double a = rx * rx + ry * ry, b = std::abs(jacobian) * scale * scale;
      // (a NaN, an infinity or b = 0 go on to the exact measure, as before)
      if (b > 0 && b <= std::numeric_limits<double>::max() && a <= threshold * b) continue;
      const double r = std::sqrt(a / std::abs(jacobian)) / scale;
      // A node not a number fails the grid whatever the others say; kept as the running
      // maximum, a later finite node would replace it (NaN compares false to everything).
      if (std::isnan(r)) return r;
      if (!(r <= largest)) {
        largest = r;
        threshold = largest * largest * (1 - 1e-9);
      }
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
