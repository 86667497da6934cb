#include "passageMesh/blade/BladeValidity.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace passageMesh {

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

bool segmentsIntersect(const Eigen::Vector2d& p1, const Eigen::Vector2d& p2,
                       const Eigen::Vector2d& q1, const Eigen::Vector2d& q2) {
  const double d1 = cross(q2 - q1, p1 - q1), d2 = cross(q2 - q1, p2 - q1);
  const double d3 = cross(p2 - p1, q1 - p1), d4 = cross(p2 - p1, q2 - p1);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  auto onSegment = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) &&
           std::min(a.y(), b.y()) <= c.y() && c.y() <= std::max(a.y(), b.y());
  };
  return (d1 == 0 && onSegment(q1, q2, p1)) || (d2 == 0 && onSegment(q1, q2, p2)) ||
         (d3 == 0 && onSegment(p1, p2, q1)) || (d4 == 0 && onSegment(p1, p2, q2));
}

}  // namespace

bool closedPolygonSelfIntersects(const std::vector<Eigen::Vector2d>& loop, int* firstEdge,
                                 int* secondEdge) {
  const int n = static_cast<int>(loop.size());
  if (n < 4) return false;
  // Sweep in x: sort edges by their left end and compare only edges whose x ranges overlap.
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto left = [&](int e) { return std::min(loop[e].x(), loop[(e + 1) % n].x()); };
  auto right = [&](int e) { return std::max(loop[e].x(), loop[(e + 1) % n].x()); };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return left(a) < left(b); });
  for (int a = 0; a < n; ++a) {
    const int e = order[a];
    for (int b = a + 1; b < n && left(order[b]) <= right(e); ++b) {
      const int f = order[b];
      const int gap = std::abs(e - f);
      if (gap == 1 || gap == n - 1) continue;  // neighbours share a vertex
      if (segmentsIntersect(loop[e], loop[(e + 1) % n], loop[f], loop[(f + 1) % n])) {
        if (firstEdge) *firstEdge = std::min(e, f);
        if (secondEdge) *secondEdge = std::max(e, f);
        return true;
      }
    }
  }
  return false;
}

BladeValidity checkBladeValidity(const BladeShape& shape) {
  const BladeParameters& p = shape.parameters();
  auto invalid = [](std::string why) { return BladeValidity{false, std::move(why)}; };
  for (double v : p.toArray())
    if (!std::isfinite(v)) return invalid("a shape parameter is not finite");
  if (p.chord <= 0) return invalid("chord is not positive");
  if (p.radiusLe <= 0 || p.radiusTe <= 0) return invalid("an edge radius is not positive");
  if (p.distLe <= 0 || p.distTe <= 0) return invalid("a camber control distance is not positive");

  constexpr int samples = 400;
  for (int k = 0; k <= samples; ++k) {
    const double u = static_cast<double>(k) / samples;
    if (shape.thickness(BladeSide::upper, u) < 0 || shape.thickness(BladeSide::lower, u) < 0)
      return invalid("negative thickness at camber parameter u = " + std::to_string(u));
    if (shape.camberDerivative(u).x() <= 0)
      return invalid("camber line not single-valued in x (dx/du <= 0 at u = " +
                     std::to_string(u) + ")");
  }

  const auto loop = shape.sampleLoop(2 * samples);
  if (closedPolygonSelfIntersects(loop)) return invalid("the sides cross (profile not simple)");

  // Extreme points of x along the closed profile: sign changes of dx between samples.
  int extremes = 0, lastSign = 0;
  const int n = static_cast<int>(loop.size());
  for (int k = 0; k <= n; ++k) {
    const double dx = loop[(k + 1) % n].x() - loop[k % n].x();
    const int sign = dx > 0 ? 1 : (dx < 0 ? -1 : 0);
    if (sign == 0) continue;
    if (lastSign != 0 && sign != lastSign) ++extremes;
    lastSign = sign;
  }
  // The loop visits the first edge twice, so the change across the start counts once.
  if (extremes != 2)
    return invalid("the profile has " + std::to_string(extremes) +
                   " extreme points in x (expected 2: leading and trailing edge)");
  return {};
}

}  // namespace passageMesh
