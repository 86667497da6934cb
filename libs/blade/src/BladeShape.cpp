#include "passageMesh/blade/BladeShape.hpp"

#include <cmath>

namespace passageMesh {

BladeShape::BladeShape(const BladeParameters& parameters)
    : parameters_(parameters),
      controlPoints_(bladeControlPoints<double>(parameters.toArray().data())),
      curves_{PiecewiseCubicCurve(controlPoints_.lower.data(), sideControlCount),
              PiecewiseCubicCurve(controlPoints_.upper.data(), sideControlCount)} {}

const std::array<Point2<double>, sideControlCount>& BladeShape::sideControlPoints(
    BladeSide side) const {
  return side == BladeSide::lower ? controlPoints_.lower : controlPoints_.upper;
}

Eigen::Vector2d BladeShape::point(BladeSide side, double u) const { return curve(side).point(u); }

Eigen::Vector2d BladeShape::derivative(BladeSide side, double u) const {
  Eigen::Vector2d c, d1, d2;
  curve(side).evaluate(u, c, d1, d2);
  return d1;
}

Eigen::Vector2d BladeShape::secondDerivative(BladeSide side, double u) const {
  Eigen::Vector2d c, d1, d2;
  curve(side).evaluate(u, c, d1, d2);
  return d2;
}

Eigen::Vector2d BladeShape::outwardNormal(BladeSide side, double u) const {
  const Eigen::Vector2d t = derivative(side, u).normalized();
  // Along the counter-clockwise loop the lower side runs with u and the upper side
  // against it; outward is the loop tangent turned -90 degrees.
  return side == BladeSide::lower ? Eigen::Vector2d(t.y(), -t.x())
                                  : Eigen::Vector2d(-t.y(), t.x());
}

double BladeShape::curvature(BladeSide side, double u) const {
  const Eigen::Vector2d d1 = derivative(side, u), d2 = secondDerivative(side, u);
  const double k = (d1.x() * d2.y() - d1.y() * d2.x()) / std::pow(d1.norm(), 3);
  return side == BladeSide::lower ? k : -k;
}

Eigen::Vector2d BladeShape::camberPoint(double u) const {
  return bezierCombine(controlPoints_.camber, BezierBasis(u).value);
}

Eigen::Vector2d BladeShape::camberDerivative(double u) const {
  return bezierCombine(controlPoints_.camber, BezierBasis(u).d1);
}

double BladeShape::camberY(double x) const {
  const double x0 = leadingEdge().x(), x1 = trailingEdge().x();
  if (x <= x0) return leadingEdge().y();
  if (x >= x1) return trailingEdge().y();
  // x(u) increases on [0, 1]: Newton's method safeguarded by bisection.
  double lo = 0, hi = 1, u = (x - x0) / (x1 - x0);
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double f = camberPoint(u).x() - x;
    if (f > 0) hi = u; else lo = u;
    const double slope = camberDerivative(u).x();
    double next = slope > 0 ? u - f / slope : 0.5 * (lo + hi);
    if (next <= lo || next >= hi) next = 0.5 * (lo + hi);
    if (std::abs(next - u) < 1e-15) break;
    u = next;
  }
  return camberPoint(u).y();
}

double BladeShape::thickness(BladeSide side, double u) const {
  const auto& p = parameters_;
  std::array<double, thicknessControlCount> t;
  t[0] = p.radiusLe;
  t[7] = p.radiusTe;
  const auto& inner = side == BladeSide::upper ? p.thicknessUpper : p.thicknessLower;
  for (int k = 0; k < 6; ++k) t[k + 1] = inner[k];
  const CubicBasis b = cubicBasis(thicknessControlCount, u);
  return combine(b, b.value, t.data()) * p.chord;
}

std::vector<double> BladeShape::sideParameters(int count) const {
  std::vector<double> u(count);
  for (int k = 0; k < count; ++k)
    u[k] = 0.5 * (1.0 - std::cos(M_PI * k / (count - 1)));
  return u;
}

std::vector<Eigen::Vector2d> BladeShape::sampleLoop(int count) const {
  // count distinct points: (count/2 + 1) on the lower side including both edges, the rest
  // on the upper side without its end points.
  const int lowerCount = count / 2 + 1;
  const int upperCount = count - lowerCount + 2;
  std::vector<Eigen::Vector2d> loop;
  loop.reserve(count);
  for (double u : sideParameters(lowerCount)) loop.push_back(point(BladeSide::lower, u));
  const auto uUpper = sideParameters(upperCount);
  for (int k = upperCount - 2; k >= 1; --k) loop.push_back(point(BladeSide::upper, uUpper[k]));
  return loop;
}

}  // namespace passageMesh
