#pragma once
// From blade shape parameters to the control points of the camber line (a cubic Bezier)
// and of the two sides (clamped cubic B-splines with 12 control points each), written
// once as a template so that bladeFit differentiates it with ceres::Jet and the rest of
// the suite evaluates it in double. Definition: docs/blade-parametrization.md.
#include <Eigen/Core>
#include <array>
#include <cmath>

#include "passageMesh/blade/CubicBSpline.hpp"

namespace passageMesh {

inline constexpr int sideControlCount = 12;      // per side
inline constexpr int thicknessControlCount = 8;  // (radius, t1..t6, radius) per side

template <typename T>
using Point2 = Eigen::Matrix<T, 2, 1>;

template <typename T>
struct BladeControlPoints {
  std::array<Point2<T>, 4> camber;                  // P0 (LE) .. P3 (TE)
  std::array<Point2<T>, sideControlCount> lower;    // leading edge -> trailing edge
  std::array<Point2<T>, sideControlCount> upper;    // leading edge -> trailing edge
};

// Cubic Bezier basis and derivatives at u (Bernstein polynomials).
struct BezierBasis {
  std::array<double, 4> value, d1, d2;
  explicit BezierBasis(double u) {
    const double v = 1.0 - u;
    value = {v * v * v, 3 * u * v * v, 3 * u * u * v, u * u * u};
    d1 = {-3 * v * v, 3 * v * v - 6 * u * v, 6 * u * v - 3 * u * u, 3 * u * u};
    d2 = {6 * v, -12 * v + 6 * u, 6 * v - 12 * u, 6 * u};
  }
};

template <typename T>
Point2<T> bezierCombine(const std::array<Point2<T>, 4>& p, const std::array<double, 4>& w) {
  return p[0] * T(w[0]) + p[1] * T(w[1]) + p[2] * T(w[2]) + p[3] * T(w[3]);
}

// Parameters in BladeParameters array order (see BladeParameters::toArray).
template <typename T>
BladeControlPoints<T> bladeControlPoints(const T* bsp) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  using std::abs;
  const double degree = M_PI / 180.0;
  const T& chord = bsp[2];
  const T stagger = bsp[3] * degree, thetaLe = bsp[4] * degree, thetaTe = bsp[5] * degree;

  BladeControlPoints<T> cp;
  cp.camber[0] = Point2<T>(bsp[0], bsp[1]);
  cp.camber[1] = cp.camber[0] + Point2<T>(cos(thetaLe), sin(thetaLe)) * (bsp[6] * chord);
  cp.camber[3] = cp.camber[0] + Point2<T>(cos(stagger), sin(stagger)) * chord;
  cp.camber[2] = cp.camber[3] - Point2<T>(cos(thetaTe), sin(thetaTe)) * (bsp[7] * chord);

  // Thickness control values (radius, t1..t6, radius) for each side, as lengths.
  std::array<T, thicknessControlCount> upperT, lowerT;
  upperT[0] = lowerT[0] = bsp[8] * chord;
  upperT[7] = lowerT[7] = bsp[9] * chord;
  for (int k = 0; k < 6; ++k) {
    upperT[k + 1] = bsp[10 + k] * chord;
    lowerT[k + 1] = bsp[16 + k] * chord;
  }

  auto unitNormal = [&](double u, Point2<T>& tangent) {
    const BezierBasis b(u);
    const Point2<T> d = bezierCombine(cp.camber, b.d1);
    tangent = d / d.norm();
    return Point2<T>(-tangent.y(), tangent.x());  // tangent turned +90 degrees
  };

  // Interior control points: the camber line at u = k/9 (k = 1..8) offset along the unit
  // normal by the side's thickness there.
  for (int k = 1; k <= 8; ++k) {
    const double u = k / 9.0;
    Point2<T> tangent;
    const Point2<T> n = unitNormal(u, tangent);
    const Point2<T> c = bezierCombine(cp.camber, BezierBasis(u).value);
    const CubicBasis tb = cubicBasis(thicknessControlCount, u);
    const T tu = combine(tb, tb.value, upperT.data());
    const T tl = combine(tb, tb.value, lowerT.data());
    cp.upper[k + 1] = c + n * tu;
    cp.lower[k + 1] = c - n * tl;
  }
  cp.upper[0] = cp.lower[0] = cp.camber[0];
  cp.upper[11] = cp.lower[11] = cp.camber[3];

  // The extra points on the edge normals. For this knot vector the curvature at a clamped
  // end is h / (3 d^2) (d = |P1 - P0|, h = distance of P2 from the end tangent line),
  // so d = sqrt(h * radius / 3) gives curvature 1 / radius at both ends of both sides.
  const T radiusLe = upperT[0], radiusTe = upperT[7];
  Point2<T> tLe, tTe;
  const Point2<T> nLe = unitNormal(0.0, tLe);
  const Point2<T> nTe = unitNormal(1.0, tTe);
  auto edgePoint = [&](const Point2<T>& end, const Point2<T>& next, const Point2<T>& tangent,
                       const Point2<T>& sideNormal, const T& radius) {
    const T h = abs((next - end).dot(tangent));
    // The 1e-9 chord floor keeps the derivative finite where h * radius -> 0 (a fit may
    // pass there) and moves the point by at most 1e-9 chord.
    const T floor = 1e-9 * chord;
    return Point2<T>(end + sideNormal * sqrt(h * radius / 3.0 + floor * floor));
  };
  cp.upper[1] = edgePoint(cp.camber[0], cp.upper[2], tLe, nLe, radiusLe);
  cp.lower[1] = edgePoint(cp.camber[0], cp.lower[2], tLe, Point2<T>(-nLe), radiusLe);
  cp.upper[10] = edgePoint(cp.camber[3], cp.upper[9], tTe, nTe, radiusTe);
  cp.lower[10] = edgePoint(cp.camber[3], cp.lower[9], tTe, Point2<T>(-nTe), radiusTe);
  return cp;
}

}  // namespace passageMesh
