#include "passageMesh/mesh/LineRedistribution.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "passageMesh/mesh/Stretching.hpp"

namespace passageMesh {

namespace {

// The point at arc length s along the polyline p (cumulative chord lengths c), on the
// Catmull-Rom curve through its nodes (end tangents from mirrored ghost nodes).
Eigen::Vector2d catmullRomAt(const std::vector<Eigen::Vector2d>& p, const std::vector<double>& c,
                             double s) {
  const int m = static_cast<int>(p.size());
  int k = static_cast<int>(std::upper_bound(c.begin(), c.end(), s) - c.begin()) - 1;
  k = std::clamp(k, 0, m - 2);
  const double t = (s - c[k]) / (c[k + 1] - c[k]);
  const Eigen::Vector2d p0 = k > 0 ? p[k - 1] : Eigen::Vector2d(2 * p[0] - p[1]);
  const Eigen::Vector2d p3 = k + 2 < m ? p[k + 2] : Eigen::Vector2d(2 * p[m - 1] - p[m - 2]);
  const Eigen::Vector2d &p1 = p[k], &p2 = p[k + 1];
  const double t2 = t * t, t3 = t2 * t;
  return 0.5 * (2 * p1 + (p2 - p0) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t2 +
                (3 * p1 - p0 - 3 * p2 + p3) * t3);
}

Eigen::Vector2d node(const StructuredBlock& b, int i, int j) { return {b.xAt(i, j), b.yAt(i, j)}; }

}  // namespace

void redistributeAlongLines(const StructuredBlock& lines, StructuredBlock& target,
                            double firstSpacing, const std::vector<Eigen::Vector2d>& wallNormals,
                            double blendLength, const std::vector<Eigen::Vector2d>& firstRowDirections) {
  if (target.ni != lines.ni || lines.nj < 2 || target.nj < 2 ||
      (!wallNormals.empty() && static_cast<int>(wallNormals.size()) < lines.ni - 1) ||
      (!firstRowDirections.empty() && (wallNormals.empty() || firstRowDirections.size() != wallNormals.size())))
    throw std::invalid_argument("redistributeAlongLines: blocks do not match");
  const int n = lines.ni - 1, outer = lines.nj - 1;
  std::vector<Eigen::Vector2d> p(static_cast<std::size_t>(lines.nj));
  std::vector<double> c(p.size(), 0.0);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < lines.nj; ++j) p[static_cast<std::size_t>(j)] = node(lines, i, j);
    for (std::size_t j = 1; j < p.size(); ++j) c[j] = c[j - 1] + (p[j] - p[j - 1]).norm();
    const Eigen::Vector2d o = node(lines, i, outer);
    const double loopSpacing = 0.5 * ((node(lines, (i + 1) % n, outer) - o).norm() +
                                      (o - node(lines, (i + n - 1) % n, outer)).norm());
    const Eigen::Vector2d b = p.front();
    const double wallSpacing = 0.5 * ((node(lines, (i + 1) % n, 0) - b).norm() +
                                      (b - node(lines, (i + n - 1) % n, 0)).norm());
    auto d = wallClusteredDistances(target.nj, c.back(), firstSpacing);
    // 90 % of the way to the loop spacing: the best of 75, 90 and 100 % on the tutorials
    // (docs/elliptic-smoothing.md has the figures).
    const double plainLast = d[d.size() - 1] - d[d.size() - 2];
    moveLastSpacing(d, plainLast + 0.9 * (loopSpacing - plainLast));
    for (int j = 0; j < target.nj; ++j) {
      Eigen::Vector2d q = j == 0 ? p.front() : j == target.nj - 1 ? p.back() : catmullRomAt(p, c, d[j]);
      // The blend ends within the line's first half: on a line shorter than the blend (a
      // tight passage) it would otherwise move the outer node off the outer loop.
      const double reach = std::min(std::max(blendLength * wallSpacing, 20 * firstSpacing), 0.5 * c.back());
      const double t = d[j] <= firstSpacing ? 0.0 : std::log(d[j] / firstSpacing) / std::log(reach / firstSpacing);
      if (!wallNormals.empty() && j > 0 && t < 1) {
        // Row 1 exactly on the normal: the first cell height is exact.
        const double w = j == 1 ? 1.0 : (1 - t) * (1 - t) * (1 + 2 * t);
        const double along = j == 1 ? firstSpacing : d[j];
        const auto& direction = j == 1 && !firstRowDirections.empty() ? firstRowDirections : wallNormals;
        q += w * (p.front() + along * direction[static_cast<std::size_t>(i)] - q);
      }
      target.xAt(i, j) = q.x();
      target.yAt(i, j) = q.y();
    }
  }
  for (int j = 0; j < target.nj; ++j) {  // the seam
    target.xAt(n, j) = target.xAt(0, j);
    target.yAt(n, j) = target.yAt(0, j);
  }
}

}  // namespace passageMesh
