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
  double best = std::numeric_limits<double>::max();
  int bestSide = 0;
  std::size_t bestIndex = 0;
  for (int s = 0; s < 2; ++s)
    for (std::size_t k = 0; k < samples_[s].size(); ++k) {
      const double d = (samples_[s][k] - q).squaredNorm();
      if (d < best) {
        best = d;
        bestSide = s;
        bestIndex = k;
      }
    }
  const BladeSide side = static_cast<BladeSide>(bestSide);
  // Newton on f(u) = (C(u) - q) . C'(u) inside the bracket of the neighbouring samples.
  const double lo = u_[bestIndex == 0 ? 0 : bestIndex - 1];
  const double hi = u_[std::min(bestIndex + 1, u_.size() - 1)];
  double u = u_[bestIndex];
  for (int iteration = 0; iteration < 20; ++iteration) {
    const CubicBasis b = cubicBasis(sideControlCount, u);
    const auto& cp = shape_.sideControlPoints(side);
    const Eigen::Vector2d r = combine(b, b.value, cp.data()) - q;
    const Eigen::Vector2d d1 = combine(b, b.d1, cp.data());
    const Eigen::Vector2d d2 = combine(b, b.d2, cp.data());
    const double f = r.dot(d1);
    double fp = d1.squaredNorm() + r.dot(d2);
    if (fp <= 0) fp = d1.squaredNorm();  // keep the step a descent step
    const double next = std::clamp(u - f / fp, lo, hi);
    const bool done = std::abs(next - u) < 1e-15;
    u = next;
    if (done) break;
  }
  FootPoint foot;
  foot.side = side;
  foot.u = u;
  foot.point = shape_.point(side, u);
  const double distance = (q - foot.point).norm();
  const Eigen::Vector2d normal = shape_.outwardNormal(side, u);
  // At the clamped ends the foot point may be off the normal; the sign still comes from
  // the side of the tangent line.
  foot.signedDistance = (q - foot.point).dot(normal) >= 0 ? distance : -distance;
  return foot;
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
