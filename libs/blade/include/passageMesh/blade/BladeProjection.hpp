#pragma once
// The nearest point of a blade profile to a given point (the foot point), by a search over
// a cosine-spaced sampling of both sides followed by Newton's method on the side parameter.
#include <Eigen/Core>
#include <vector>

#include "passageMesh/blade/BladeShape.hpp"

namespace passageMesh {

struct FootPoint {
  BladeSide side = BladeSide::lower;
  double u = 0;                // side parameter of the foot point
  Eigen::Vector2d point;       // the foot point on the profile
  double signedDistance = 0;   // > 0 outside the blade, < 0 inside
};

class BladeProjector {
 public:
  explicit BladeProjector(const BladeShape& shape, int samplesPerSide = 256);
  // The foot point of q, by a search over the whole profile.
  FootPoint project(const Eigen::Vector2d& q) const;

 private:
  double newton(BladeSide side, const Eigen::Vector2d& q, double u, double lo, double hi) const;
  FootPoint footPoint(BladeSide side, double u, const Eigen::Vector2d& q) const;

  const BladeShape& shape_;
  std::vector<double> u_;
  std::vector<Eigen::Vector2d> samples_[2];
};

// Mean and maximum unsigned distance of `points` from the profile.
struct Deviation {
  double mean = 0;
  double max = 0;
  int maxIndex = -1;
};
Deviation deviationFromProfile(const BladeShape& shape, const std::vector<Eigen::Vector2d>& points);

}  // namespace passageMesh
