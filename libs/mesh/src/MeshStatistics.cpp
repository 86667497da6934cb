#include "passageMesh/mesh/MeshStatistics.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

namespace passageMesh {

WallLayerStatistics wallLayerStatistics(const StructuredBlock& o, double firstCellHeight) {
  const int n = o.ni - 1;
  WallLayerStatistics s;
  int within = 0;
  double angleSum = 0;
  for (int i = 0; i < n; ++i) {
    const int e = (i + 1) % n, w = (i + n - 1) % n;
    const Eigen::Vector2d normal =
        discreteWallNormal(Eigen::Vector2d(o.xAt(w, 0), o.yAt(w, 0)), Eigen::Vector2d(o.xAt(e, 0), o.yAt(e, 0)));
    const Eigen::Vector2d tangent(normal.y(), -normal.x());
    const Eigen::Vector2d line(o.xAt(i, 1) - o.xAt(i, 0), o.yAt(i, 1) - o.yAt(i, 0));
    const double error = std::abs(line.dot(normal) / firstCellHeight - 1);
    if (error <= 0.02) ++within;
    if (error > s.heightMaxError) {
      s.heightMaxError = error;
      s.heightWorstNode = i;
    }
    const double angle = std::acos(std::clamp(line.normalized().dot(tangent), -1.0, 1.0));
    const double deviation = std::abs(angle * 180 / M_PI - 90);
    angleSum += deviation;
    if (deviation > s.angleMaxDeviation) {
      s.angleMaxDeviation = deviation;
      s.angleWorstNode = i;
    }
  }
  s.heightWithin2Percent = static_cast<double>(within) / n;
  s.angleMeanDeviation = angleSum / n;
  return s;
}

}  // namespace passageMesh
