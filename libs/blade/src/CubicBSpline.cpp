#include "passageMesh/blade/CubicBSpline.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace passageMesh {

std::vector<double> clampedUniformKnots(int controlCount) {
  if (controlCount < 4) throw std::invalid_argument("a cubic B-spline needs 4 control values");
  const int spans = controlCount - 3;
  std::vector<double> knots(controlCount + 4);
  for (int k = 0; k < 4; ++k) {
    knots[k] = 0.0;
    knots[controlCount + k] = 1.0;
  }
  for (int k = 1; k < spans; ++k) knots[3 + k] = static_cast<double>(k) / spans;
  return knots;
}

namespace {

CubicBasis cubicBasisDeBoor(int controlCount, double u) {
  // Uniform interior knots: work in the local coordinate of the span and use the
  // Cox-de Boor recursion on the knot vector (the clamped end spans are not uniform).
  const int spans = controlCount - 3;
  u = std::clamp(u, 0.0, 1.0);
  const int span = std::min(static_cast<int>(u * spans), spans - 1);  // 0-based span
  // Knot function: t(k) for the full clamped vector, index k in [0, controlCount+3].
  auto knot = [&](int k) {
    if (k <= 3) return 0.0;
    if (k >= controlCount) return 1.0;
    return static_cast<double>(k - 3) / spans;
  };
  const int i = span + 3;  // knot index with knot(i) <= u < knot(i+1)
  // Degree-0..3 basis by the triangular scheme (The NURBS Book, A2.3, written anew).
  double ndu[4][4];
  double left[4], right[4];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= 3; ++j) {
    left[j] = u - knot(i + 1 - j);
    right[j] = knot(i + j) - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  CubicBasis b;
  b.first = i - 3;
  double a[2][4];
  for (int r = 0; r <= 3; ++r) {
    b.value[r] = ndu[r][3];
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    double ders[3] = {ndu[r][3], 0.0, 0.0};
    for (int k = 1; k <= 2; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = 3 - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : 3 - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k] = d;
      std::swap(s1, s2);
    }
    b.d1[r] = ders[1] * 3.0;
    b.d2[r] = ders[2] * 6.0;
  }
  return b;
}


// On each span a basis function is a cubic polynomial, stored by its Taylor coefficients
// about the span's midpoint; evaluating that is several times faster than the
// recursion, and the bladeFit projection evaluates the basis millions of times.
struct SpanPolynomials {
  int spans = 0;
  // [span][k][power]: N_{span+k}(t) = sum_p c[p] t^p, t = u - (span midpoint)
  std::vector<std::array<std::array<double, 4>, 4>> coefficients;

  explicit SpanPolynomials(int controlCount) : spans(controlCount - 3) {
    coefficients.resize(spans);
    const double h = 1.0 / spans;
    for (int span = 0; span < spans; ++span) {
      // Expanded about the span's midpoint: both evaluations lie strictly inside the span
      // (a knot evaluated in floating point may land in the neighbouring span). The second
      // derivative is linear on the span, which gives the constant third derivative.
      const CubicBasis middle = cubicBasisDeBoor(controlCount, (span + 0.5) * h);
      const CubicBasis quarter = cubicBasisDeBoor(controlCount, (span + 0.25) * h);
      for (int k = 0; k < 4; ++k)
        coefficients[span][k] = {middle.value[k], middle.d1[k], 0.5 * middle.d2[k],
                                 (middle.d2[k] - quarter.d2[k]) / (0.25 * h) / 6.0};
    }
  }
};

const SpanPolynomials& spanPolynomials(int controlCount) {
  // The suite uses 8 (thickness) and 12 (sides) control values; others are built once.
  static const SpanPolynomials eight(8), twelve(12);
  if (controlCount == 8) return eight;
  if (controlCount == 12) return twelve;
  thread_local std::vector<std::unique_ptr<SpanPolynomials>> others(64);
  if (controlCount >= 64) throw std::invalid_argument("cubicBasis: too many control values");
  if (!others[controlCount]) others[controlCount] = std::make_unique<SpanPolynomials>(controlCount);
  return *others[controlCount];
}

}  // namespace

CubicBasis cubicBasis(int controlCount, double u) {
  const SpanPolynomials& table = spanPolynomials(controlCount);
  u = std::clamp(u, 0.0, 1.0);
  const int span = std::min(static_cast<int>(u * table.spans), table.spans - 1);
  const double t = u - (span + 0.5) / table.spans;
  CubicBasis b;
  b.first = span;
  for (int k = 0; k < 4; ++k) {
    const auto& c = table.coefficients[span][k];
    b.value[k] = c[0] + t * (c[1] + t * (c[2] + t * c[3]));
    b.d1[k] = c[1] + t * (2 * c[2] + t * 3 * c[3]);
    b.d2[k] = 2 * c[2] + t * 6 * c[3];
  }
  return b;
}

PiecewiseCubicCurve::PiecewiseCubicCurve(const Eigen::Vector2d* control, int controlCount)
    : spans_(controlCount - 3), coefficients_(controlCount - 3) {
  const SpanPolynomials& table = spanPolynomials(controlCount);
  for (int j = 0; j < spans_; ++j)
    for (int p = 0; p < 4; ++p) {
      Eigen::Vector2d c = Eigen::Vector2d::Zero();
      for (int k = 0; k < 4; ++k) c += table.coefficients[j][k][p] * control[j + k];
      coefficients_[j][p] = c;
    }
}

int PiecewiseCubicCurve::span(double u, double& t) const {
  u = std::clamp(u, 0.0, 1.0);
  const int j = std::min(static_cast<int>(u * spans_), spans_ - 1);
  t = u - (j + 0.5) / spans_;
  return j;
}

void PiecewiseCubicCurve::evaluate(double u, Eigen::Vector2d& point, Eigen::Vector2d& d1,
                                   Eigen::Vector2d& d2) const {
  double t;
  const auto& c = coefficients_[span(u, t)];
  point = c[0] + t * (c[1] + t * (c[2] + t * c[3]));
  d1 = c[1] + t * (2 * c[2] + t * 3 * c[3]);
  d2 = 2 * c[2] + t * 6 * c[3];
}

Eigen::Vector2d PiecewiseCubicCurve::point(double u) const {
  double t;
  const auto& c = coefficients_[span(u, t)];
  return c[0] + t * (c[1] + t * (c[2] + t * c[3]));
}

}  // namespace passageMesh
