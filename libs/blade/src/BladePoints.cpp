#include "passageMesh/blade/BladePoints.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "passageMesh/blade/BladeValidity.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/NumberFormat.hpp"

namespace passageMesh {

OrderedBladePoints orderBladePoints(const PointSet& input) {
  OrderedBladePoints out;
  out.points = input.points;
  out.inputIndex.resize(out.points.size());
  std::iota(out.inputIndex.begin(), out.inputIndex.end(), 0);
  if (out.points.size() >= 2 && out.points.front() == out.points.back()) {
    out.points.pop_back();  // a closed loop: the repeated point is not a duplicate
    out.inputIndex.pop_back();
    out.closed = true;
  }
  auto lineOf = [&](int index) { return input.lines.empty() ? index + 1 : input.lines[index]; };
  const int n = static_cast<int>(out.points.size());
  if (n < minimumBladePoints)
    throw InputError(input.file, 0,
                     "only " + std::to_string(n) + " distinct points, expected at least " +
                         std::to_string(minimumBladePoints) + " 'x y' points along the profile");

  // Far outside any blade's size the fit's arithmetic overflows or underflows (points
  // scaled by 1e300 crashed it, by 1e-155 it returned another shape): refused here, before
  // any norm is taken.
  Eigen::Vector2d lowest = out.points[0], highest = out.points[0];
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d& p = out.points[k];
    if (p.cwiseAbs().maxCoeff() > maximumBladeCoordinate)
      throw InputError(input.file, lineOf(k),
                       "coordinate beyond +-" + formatRounded(maximumBladeCoordinate) +
                           "; expected blade points in metres");
    lowest = lowest.cwiseMin(p);
    highest = highest.cwiseMax(p);
  }
  const double size = (highest - lowest).maxCoeff();
  if (size < minimumBladeSize || size > maximumBladeSize)
    throw InputError(input.file, 0,
                     "the points span " + formatRounded(size) + "; expected a blade between " +
                         formatRounded(minimumBladeSize) + " and " + formatRounded(maximumBladeSize) + " across");

  // Exact duplicates (after sorting), reported with both lines.
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    return std::make_pair(out.points[a].x(), out.points[a].y()) <
           std::make_pair(out.points[b].x(), out.points[b].y());
  };
  std::sort(order.begin(), order.end(), less);
  for (int k = 1; k < n; ++k)
    if (out.points[order[k]] == out.points[order[k - 1]]) {
      const int a = std::min(order[k], order[k - 1]), b = std::max(order[k], order[k - 1]);
      throw InputError(input.file, lineOf(b),
                       "duplicate point (same as line " + std::to_string(lineOf(a)) +
                           "); expected each profile point once");
    }

  int first = -1, second = -1;
  if (closedPolygonSelfIntersects(out.points, &first, &second))
    throw InputError(input.file, lineOf(second),
                     "the point loop intersects itself (segment from line " +
                         std::to_string(lineOf(first)) + " crosses the one from line " +
                         std::to_string(lineOf(second)) +
                         "); expected points in order along the profile");

  // Shoelace about the first point: far from the origin the absolute form cancels.
  double area2 = 0, extent = 0;
  const Eigen::Vector2d origin = out.points[0];
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d a = out.points[k] - origin, b = out.points[(k + 1) % n] - origin;
    area2 += a.x() * b.y() - b.x() * a.y();
    extent = std::max(extent, a.norm());
  }
  if (std::abs(area2) <= 1e-12 * extent * extent)
    throw InputError(input.file, 0, "the point loop encloses no area");
  if (area2 < 0) {
    std::reverse(out.points.begin(), out.points.end());
    std::reverse(out.inputIndex.begin(), out.inputIndex.end());
    out.reversed = true;
  }
  return out;
}

}  // namespace passageMesh
