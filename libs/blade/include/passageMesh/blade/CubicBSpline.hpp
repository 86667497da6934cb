#pragma once
// Clamped cubic B-splines with uniform interior knots: the basis functions and their first
// two derivatives at a parameter u in [0, 1]. The basis is plain double because every
// spline in the suite is evaluated at known parameters; only control values may carry
// derivative types (ceres::Jet), which keeps automatic differentiation cheap.
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

}  // namespace passageMesh
