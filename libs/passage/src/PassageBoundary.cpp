#include "passageMesh/passage/PassageBoundary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace passageMesh {

PassageBoundary::PassageBoundary(const BladeShape& blade, const PassageCondition& condition,
                                 const MeshingParameters& parameters)
    : blade_(blade),
      condition_(condition),
      parameters_(parameters),
      le_(blade.leadingEdge()),
      te_(blade.trailingEdge()) {
  const double chord = blade.parameters().chord, axial = te_.x() - le_.x();
  const double limit = std::min(0.2 * chord, 0.25 * axial);
  leadingFillet_ = filletAt(le_.x(), std::min(limit, 0.5 * (le_.x() - inletInterfaceX())));
  trailingFillet_ = filletAt(te_.x(), std::min(limit, 0.5 * (outletInterfaceX() - te_.x())));
}

PassageBoundary::Fillet PassageBoundary::filletAt(double xKink, double halfWidth) const {
  Fillet f;
  if (!(halfWidth > 0)) return f;
  f.x0 = xKink - halfWidth;
  f.x1 = xKink + halfWidth;
  f.y0 = pieceY(f.x0);
  f.y1 = pieceY(f.x1);
  // One-sided slopes, each inside its own piece.
  const double h = 1e-4 * halfWidth;
  f.slope0 = (f.y0 - pieceY(f.x0 - h)) / h;
  f.slope1 = (pieceY(f.x1 + h) - f.y1) / h;
  return f;
}

double PassageBoundary::Fillet::y(double x) const {
  const double w = x1 - x0, t = (x - x0) / w, t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * w * slope0 + (-2 * t3 + 3 * t2) * y1 +
         (t3 - t2) * w * slope1;
}

double PassageBoundary::lowerY(double x) const {
  if (leadingFillet_.covers(x)) return leadingFillet_.y(x);
  if (trailingFillet_.covers(x)) return trailingFillet_.y(x);
  return pieceY(x);
}

double PassageBoundary::pieceY(double x) const {
  const double halfPitch = 0.5 * condition_.pitch;
  const double yInlet = le_.y() + parameters_.yIn - halfPitch;
  const double yOutlet = te_.y() + parameters_.yOut - halfPitch;
  if (x < le_.x()) return yInlet;
  if (x >= te_.x()) return yOutlet;

  const double yCamber = blade_.camberY(x);
  const double sx = (te_.x() - x) / (te_.x() - le_.x());
  const double d = 0.05 * blade_.parameters().chord;
  const double D = le_.y() - te_.y();
  const double w = D * D / (D * D + d * d);
  const double s = D * (yCamber - te_.y()) / (D * D + d * d) + (1 - w) * sx;
  const double yC = yCamber + parameters_.yIn * s + parameters_.yOut * (1 - s) - halfPitch;
  const double yL = yInlet + (yOutlet - yInlet) * (1 - sx);
  const double a = parameters_.alphaCamber;
  return a * yC + (1 - a) * yL;
}

namespace {

// Distance from p to the segment a-b.
double segmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

}  // namespace

double bladeClearance(const BladeShape& blade, const PassageBoundary& boundary) {
  constexpr int samples = 400;
  const double xA = boundary.inletInterfaceX(), xB = boundary.outletInterfaceX();
  // The loop as a polyline: lower periodic, outlet interface, upper periodic (backwards),
  // inlet interface, closed.
  std::vector<Eigen::Vector2d> loop;
  for (int k = 0; k <= samples; ++k) {
    const double x = xA + (xB - xA) * k / samples;
    loop.emplace_back(x, boundary.lowerY(x));
  }
  for (int k = samples; k >= 0; --k) {
    const double x = xA + (xB - xA) * k / samples;
    loop.emplace_back(x, boundary.upperY(x));
  }
  loop.push_back(loop.front());
  double clearance = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& p : blade.sampleLoop(2 * samples)) {
    // A blade point beyond an interface or beyond a periodic boundary is outside the loop.
    const bool inside = p.x() > xA && p.x() < xB && p.y() > boundary.lowerY(p.x()) &&
                        p.y() < boundary.upperY(p.x());
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k + 1 < loop.size(); ++k)
      nearest = std::min(nearest, segmentDistance(p, loop[k], loop[k + 1]));
    clearance = std::min(clearance, inside ? nearest : -nearest);
  }
  return clearance;
}

BladeYExtent widestYExtent(const BladeShape& blade) {
  const std::vector<Eigen::Vector2d> loop = blade.sampleLoop(2000);
  const std::size_t n = loop.size();
  BladeYExtent widest;
  for (std::size_t s = 0; s < n; s += 4) {
    const double x = loop[s].x();
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Vector2d& a = loop[k];
      const Eigen::Vector2d& b = loop[(k + 1) % n];
      if (std::min(a.x(), b.x()) > x || std::max(a.x(), b.x()) < x) continue;
      // Where the segment a-b crosses the vertical through x (a vertical segment: both ends).
      if (a.x() == b.x()) {
        low = std::min({low, a.y(), b.y()});
        high = std::max({high, a.y(), b.y()});
      } else {
        const double y = a.y() + (x - a.x()) / (b.x() - a.x()) * (b.y() - a.y());
        low = std::min(low, y);
        high = std::max(high, y);
      }
    }
    if (high - low > widest.extent) widest = {high - low, x};
  }
  return widest;
}

}  // namespace passageMesh
