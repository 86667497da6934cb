#include "passageMesh/mesh/BladeNodes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "passageMesh/mesh/ArcLengthTable.hpp"
#include "passageMesh/mesh/Stretching.hpp"

namespace passageMesh {

namespace {

// Arc length along one side from the leading edge (u = 0), on 4000 cosine-spaced samples
// (dense at the edges, where curvature is highest): the polygon is shorter than the
// curve by ~1e-8 relative.
ArcLengthTable sideArcLength(const BladeShape& blade, BladeSide side) {
  std::vector<double> u = blade.sideParameters(4000);
  std::vector<Eigen::Vector2d> points;
  points.reserve(u.size());
  for (double uk : u) points.push_back(blade.point(side, uk));
  return ArcLengthTable(std::move(u), points);
}

}  // namespace

std::vector<BladeNode> distributeBladeNodes(const BladeShape& blade, int nT, double gammaLe,
                                            double gammaTe) {
  if (nT < 8) throw std::invalid_argument("distributeBladeNodes: need at least 8 nodes");
  const ArcLengthTable lower = sideArcLength(blade, BladeSide::lower);
  const ArcLengthTable upper = sideArcLength(blade, BladeSide::upper);
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
    add(BladeSide::lower, k == 0 ? 1.0 : lower.parameterAt(lower.length() - fromTrailingEdge));
  }
  // Upper side, leading edge (xi = 0) to trailing edge (xi = 1, not included).
  for (int k = 0; k < nUpper; ++k) {
    const double xi = static_cast<double>(k) / nUpper;
    add(BladeSide::upper, k == 0 ? 0.0 : upper.parameterAt(upper.length() * tanhStretch(xi, gammaLe, gammaTe)));
  }
  return nodes;
}

}  // namespace passageMesh
