#include "passageMesh/blade/BladeProjection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace passageMesh {

BladeProjector::BladeProjector(const BladeShape& shape, int samplesPerSide)
    : shape_(shape), u_(shape.sideParameters(samplesPerSide)) {
  for (int s = 0; s < 2; ++s)
    for (double u : u_) samples_[s].push_back(shape.point(static_cast<BladeSide>(s), u));
}

FootPoint BladeProjector::project(const Eigen::Vector2d& q) const {
  // The nearest sample of each side, refined by Newton's method on
  // f(u) = (C(u) - q) . C'(u) within the bracket of its neighbouring samples; the nearer
  // of the two refined points is the foot point. Refining both sides matters near a thin
  // edge, where the nearest sample may lie on the other side.
  FootPoint best;
  double bestDistance = std::numeric_limits<double>::max();
  for (int s = 0; s < 2; ++s) {
    const BladeSide side = static_cast<BladeSide>(s);
    std::size_t nearest = 0;
    double nearestDistance = std::numeric_limits<double>::max();
    for (std::size_t k = 0; k < samples_[s].size(); ++k) {
      const double d = (samples_[s][k] - q).squaredNorm();
      if (d < nearestDistance) {
        nearestDistance = d;
        nearest = k;
      }
    }
    const double lo = u_[nearest == 0 ? 0 : nearest - 1];
    const double hi = u_[std::min(nearest + 1, u_.size() - 1)];
    const auto& cp = shape_.sideControlPoints(side);
    double u = u_[nearest];
    Eigen::Vector2d point = samples_[s][nearest];
    for (int iteration = 0; iteration < 30; ++iteration) {
      const CubicBasis b = cubicBasis(sideControlCount, u);
      point = combine(b, b.value, cp.data());
      const Eigen::Vector2d r = point - q;
      const Eigen::Vector2d d1 = combine(b, b.d1, cp.data());
      const Eigen::Vector2d d2 = combine(b, b.d2, cp.data());
      double fp = d1.squaredNorm() + r.dot(d2);
      if (fp <= 0) fp = d1.squaredNorm();  // keep the step a descent step
      const double next = std::clamp(u - r.dot(d1) / fp, lo, hi);
      // The distance is stationary at the foot point, so 1e-11 in u is far below
      // round-off in the distance.
      const bool done = std::abs(next - u) < 1e-11;
      u = next;
      if (done) break;
    }
    point = shape_.point(side, u);
    const double distance = (q - point).squaredNorm();
    if (distance < bestDistance) {
      bestDistance = distance;
      best.side = side;
      best.u = u;
      best.point = point;
    }
  }
  const double distance = std::sqrt(bestDistance);
  const Eigen::Vector2d normal = shape_.outwardNormal(best.side, best.u);
  // At the clamped ends the foot point may be off the normal; the sign still comes from
  // the side of the tangent line.
  best.signedDistance = (q - best.point).dot(normal) >= 0 ? distance : -distance;
  return best;
}

Deviation deviationFromProfile(const BladeShape& shape,
                               const std::vector<Eigen::Vector2d>& points) {
  const BladeProjector projector(shape);
  Deviation d;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double distance = std::abs(projector.project(points[k]).signedDistance);
    d.mean += distance;
    if (distance > d.max) {
      d.max = distance;
      d.maxIndex = static_cast<int>(k);
    }
  }
  if (!points.empty()) d.mean /= static_cast<double>(points.size());
  return d;
}

}  // namespace passageMesh
