#pragma once
// A blade section built from its shape parameters: camber line, the two sides, normals and
// curvature, and a closed-loop sampling. Coordinates in metres; a side parameter u runs
// from the leading edge (u = 0) to the trailing edge (u = 1) on both sides.
//
// The closed profile is counter-clockwise: the lower side from the leading to the trailing
// edge, then the upper side back. "Lower" is the side at -normal of the camber line (its
// normal is the camber tangent turned +90 degrees): for a turbine blade with negative
// stagger, the lower side is the pressure side.
#include <Eigen/Core>
#include <vector>

#include "passageMesh/blade/BladeControlPoints.hpp"
#include "passageMesh/blade/BladeParameters.hpp"

namespace passageMesh {

enum class BladeSide { lower = 0, upper = 1 };

class BladeShape {
 public:
  explicit BladeShape(const BladeParameters& parameters);

  const BladeParameters& parameters() const { return parameters_; }
  const BladeControlPoints<double>& controlPoints() const { return controlPoints_; }
  const std::array<Point2<double>, sideControlCount>& sideControlPoints(BladeSide side) const;

  Eigen::Vector2d leadingEdge() const { return controlPoints_.camber[0]; }
  Eigen::Vector2d trailingEdge() const { return controlPoints_.camber[3]; }

  Eigen::Vector2d point(BladeSide side, double u) const;
  Eigen::Vector2d derivative(BladeSide side, double u) const;        // d/du
  Eigen::Vector2d secondDerivative(BladeSide side, double u) const;  // d2/du2
  // Unit normal pointing out of the blade.
  Eigen::Vector2d outwardNormal(BladeSide side, double u) const;
  // Signed curvature of the closed counter-clockwise profile (positive where convex).
  double curvature(BladeSide side, double u) const;

  Eigen::Vector2d camberPoint(double u) const;
  Eigen::Vector2d camberDerivative(double u) const;
  // The camber line's y at x, for x between the camber line's end points (clamped
  // outside); the camber line of a valid blade is single-valued in x.
  double camberY(double x) const;
  // The side's half-thickness function (a length) at camber parameter u.
  double thickness(BladeSide side, double u) const;

  // The closed profile as `count` distinct points, counter-clockwise, starting at the
  // leading edge, clustered (cosine spacing in u) towards both edges.
  std::vector<Eigen::Vector2d> sampleLoop(int count) const;
  // One side sampled at `count` parameters with cosine spacing, leading to trailing edge.
  std::vector<double> sideParameters(int count) const;

  // The side as piecewise polynomials, for fast repeated evaluation.
  const PiecewiseCubicCurve& curve(BladeSide side) const { return curves_[static_cast<int>(side)]; }

 private:
  BladeParameters parameters_;
  BladeControlPoints<double> controlPoints_;
  std::array<PiecewiseCubicCurve, 2> curves_;  // lower, upper
};

}  // namespace passageMesh
