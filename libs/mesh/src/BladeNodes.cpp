#include "passageMesh/mesh/BladeNodes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "passageMesh/mesh/Stretching.hpp"

namespace passageMesh {

SideArcLength::SideArcLength(const BladeShape& blade, BladeSide side, int samples)
    : u_(blade.sideParameters(samples)), s_(u_.size(), 0.0) {
  // Chords of a cosine-spaced polygon (dense at the edges, where curvature is highest);
  // with 4000 samples the polygon is shorter than the curve by ~1e-8 relative.
  Eigen::Vector2d last = blade.point(side, u_[0]);
  for (std::size_t k = 1; k < u_.size(); ++k) {
    const Eigen::Vector2d p = blade.point(side, u_[k]);
    s_[k] = s_[k - 1] + (p - last).norm();
    last = p;
  }
}

double SideArcLength::uAt(double s) const {
  if (s <= 0) return 0.0;
  if (s >= s_.back()) return 1.0;
  const auto it = std::upper_bound(s_.begin(), s_.end(), s);
  const std::size_t k = static_cast<std::size_t>(it - s_.begin());
  const double t = (s - s_[k - 1]) / (s_[k] - s_[k - 1]);
  return u_[k - 1] + t * (u_[k] - u_[k - 1]);
}

std::vector<BladeNode> distributeBladeNodes(const BladeShape& blade, int nT, double gammaLe,
                                            double gammaTe) {
  if (nT < 8) throw std::invalid_argument("distributeBladeNodes: need at least 8 nodes");
  const SideArcLength lower(blade, BladeSide::lower), upper(blade, BladeSide::upper);
  // Intervals per side in proportion to length, at least 2 each.
  const int nLower = std::clamp(
      static_cast<int>(std::lround(nT * lower.length() / (lower.length() + upper.length()))), 2,
      nT - 2);
  const int nUpper = nT - nLower;

  std::vector<BladeNode> nodes;
  nodes.reserve(nT);
  auto add = [&](BladeSide side, double u) {
    BladeNode n;
    n.side = side;
    n.u = u;
    n.point = blade.point(side, u);
    n.outwardNormal = blade.outwardNormal(side, u);
    nodes.push_back(n);
  };
  // Lower side, trailing edge (xi = 0) to leading edge (xi = 1, not included).
  for (int k = 0; k < nLower; ++k) {
    const double xi = static_cast<double>(k) / nLower;
    const double fromTrailingEdge = lower.length() * tanhStretch(xi, gammaTe, gammaLe);
    add(BladeSide::lower, k == 0 ? 1.0 : lower.uAt(lower.length() - fromTrailingEdge));
  }
  // Upper side, leading edge (xi = 0) to trailing edge (xi = 1, not included).
  for (int k = 0; k < nUpper; ++k) {
    const double xi = static_cast<double>(k) / nUpper;
    add(BladeSide::upper, k == 0 ? 0.0 : upper.uAt(upper.length() * tanhStretch(xi, gammaLe, gammaTe)));
  }
  return nodes;
}

}  // namespace passageMesh
