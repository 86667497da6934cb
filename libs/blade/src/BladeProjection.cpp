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

double BladeProjector::newton(BladeSide side, const Eigen::Vector2d& q, double u, double lo,
                              double hi) const {
  // Newton on f(u) = (C(u) - q) . C'(u), kept inside [lo, hi].
  const PiecewiseCubicCurve& curve = shape_.curve(side);
  Eigen::Vector2d c, d1, d2;
  for (int iteration = 0; iteration < 30; ++iteration) {
    curve.evaluate(u, c, d1, d2);
    const Eigen::Vector2d r = c - q;
    double fp = d1.squaredNorm() + r.dot(d2);
    if (fp <= 0) fp = d1.squaredNorm();  // keep the step a descent step
    const double next = std::clamp(u - r.dot(d1) / fp, lo, hi);
    // The distance is stationary at the foot point: an error of 1e-9 in u changes it by
    // about 1e-18 chord.
    const bool done = std::abs(next - u) < 1e-9;
    u = next;
    if (done) break;
  }
  return u;
}

FootPoint BladeProjector::footPoint(BladeSide side, double u, const Eigen::Vector2d& q) const {
  FootPoint foot;
  foot.side = side;
  foot.u = u;
  foot.point = shape_.point(side, u);
  const double distance = (q - foot.point).norm();
  // At the clamped ends the foot point may be off the normal; the sign still comes from
  // the side of the tangent line.
  foot.signedDistance =
      (q - foot.point).dot(shape_.outwardNormal(side, u)) >= 0 ? distance : -distance;
  return foot;
}

FootPoint BladeProjector::project(const Eigen::Vector2d& q) const {
  // The nearest sample of each side, refined by Newton's method within the bracket of its
  // neighbouring samples; the nearer of the two refined points is the foot point.
  // Refining both sides matters near a thin edge, where the nearest sample may lie on the
  // other side.
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
    const FootPoint foot = footPoint(side, newton(side, q, u_[nearest], lo, hi), q);
    if (std::abs(foot.signedDistance) < bestDistance) {
      bestDistance = std::abs(foot.signedDistance);
      best = foot;
    }
  }
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
