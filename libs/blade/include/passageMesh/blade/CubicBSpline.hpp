#pragma once
// Clamped cubic B-splines with uniform interior knots: the basis functions and their first
// two derivatives at a parameter u in [0, 1]. The basis is plain double because every
// spline in the suite is evaluated at known parameters; only control values may carry
// derivative types (ceres::Jet), which keeps automatic differentiation cheap.
#include <Eigen/Core>
#include <array>
#include <vector>

namespace passageMesh {

struct CubicBasis {
  int first = 0;                    // index of the first of the 4 active control values
  std::array<double, 4> value{};    // N_{first+k}(u)
  std::array<double, 4> d1{};       // dN/du
  std::array<double, 4> d2{};       // d2N/du2
};

// Knot vector [0,0,0,0, 1/(n-3), ..., (n-4)/(n-3), 1,1,1,1] for n control values (n >= 4).
std::vector<double> clampedUniformKnots(int controlCount);

// Basis of the clamped uniform cubic spline with `controlCount` control values at u
// (clamped to [0, 1]; u = 1 belongs to the last span).
CubicBasis cubicBasis(int controlCount, double u);

// sum_k N_k(u) c_k for any value type with + and scalar *.
template <typename Value>
Value combine(const CubicBasis& b, const std::array<double, 4>& weights, const Value* control) {
  Value sum = control[b.first] * weights[0];
  for (int k = 1; k < 4; ++k) sum = sum + control[b.first + k] * weights[k];
  return sum;
}

// A clamped uniform cubic B-spline curve in the plane, converted once to one cubic
// polynomial per span (Taylor form about the span's midpoint). Evaluating it costs about
// twenty flops, against the basis recursion's hundreds: the foot-point projections of
// bladeFit and the mesher's boundary sampling evaluate curves millions of times.
class PiecewiseCubicCurve {
 public:
  PiecewiseCubicCurve() = default;
  PiecewiseCubicCurve(const Eigen::Vector2d* control, int controlCount);

  void evaluate(double u, Eigen::Vector2d& point, Eigen::Vector2d& d1, Eigen::Vector2d& d2) const;
  Eigen::Vector2d point(double u) const;

 private:
  int span(double u, double& t) const;
  int spans_ = 0;
  std::vector<std::array<Eigen::Vector2d, 4>> coefficients_;  // [span][power]
};

}  // namespace passageMesh
