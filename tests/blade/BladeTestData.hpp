#pragma once
// Shared test data: typical blades, ParaBlade's reference parameters (shared/blades/README.md)
// and ParaBlade's own way of placing a section in the physical frame.
#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "passageMesh/blade/BladeProjection.hpp"
#include "passageMesh/blade/BladeShape.hpp"

namespace passageMesh::testData {

inline std::filesystem::path tutorialPoints(const std::string& name) {
  return std::filesystem::path(PASSAGEMESH_SOURCE_DIR) / "tutorials" / name / "constant" /
         "bladePoints.dat";
}

inline BladeParameters typicalTurbineBlade() {
  BladeParameters p;
  p.xLe = 0.01;
  p.yLe = -0.02;
  p.chord = 0.07;
  p.stagger = -40;
  p.thetaLe = 10;
  p.thetaTe = -65;
  p.distLe = 0.4;
  p.distTe = 0.4;
  p.radiusLe = 0.05;
  p.radiusTe = 0.01;
  p.thicknessUpper = {0.15, 0.14, 0.12, 0.08, 0.04, 0.015};
  p.thicknessLower = {0.06, 0.06, 0.05, 0.035, 0.02, 0.01};
  return p;
}

// ParaBlade's camber/thickness parameters (angles in degrees, lengths in units of the
// axial chord) and the section's physical placement.
struct ParaBladeSection {
  double stagger, thetaIn, thetaOut, radiusIn, radiusOut, distIn, distOut;
  double upper[6], lower[6];
  double xLeading, yLeading, xTrailing;
};

inline ParaBladeSection paraBladeSIRT() {
  return {0.11172,   43.243,    -43.2051,  0.0001,    0.0001,    0.592561, 0.59349,
          {0.0001, 0.0132815, 0.0439629, 0.0442705, 0.0144723, 0.0001},
          {0.0001, 0.030939, 0.0595462, 0.0594614, 0.0312254, 0.0001},
          -0.0848174, 0.0222599, 0.0844339};
}

inline ParaBladeSection paraBladeLS89() {
  return {-54.8679, 6.04538,  -75.0264, 0.17042, 0.0114218, 0.450155, 0.536345,
          {0.443529, 0.345379, 0.223858, 0.10876, 0.0438611, 0.0119103},
          {0.0837768, 0.170314, 0.115641, 0.0407775, 0.0351989, 0.0263177},
          8.36113e-05, 0.000199478, 0.0368689};
}

// ParaBlade builds the section with unit axial chord and maps the profile's x extent onto
// [xLeading, xTrailing] while y is scaled by the axial length and shifted by yLeading.
inline std::vector<Eigen::Vector2d> paraBladeProfile(const ParaBladeSection& s, int count) {
  const double c = 1.0 / std::cos(s.stagger * M_PI / 180.0);
  BladeParameters p;
  p.chord = c;
  p.stagger = s.stagger;
  p.thetaLe = s.thetaIn;
  p.thetaTe = s.thetaOut;
  p.distLe = s.distIn / c;
  p.distTe = s.distOut / c;
  p.radiusLe = s.radiusIn / c;
  p.radiusTe = s.radiusOut / c;
  for (int k = 0; k < 6; ++k) {
    p.thicknessUpper[k] = s.upper[k] / c;
    p.thicknessLower[k] = s.lower[k] / c;
  }
  auto loop = BladeShape(p).sampleLoop(count);
  double xmin = std::numeric_limits<double>::max(), xmax = -xmin;
  for (const auto& q : loop) {
    xmin = std::min(xmin, q.x());
    xmax = std::max(xmax, q.x());
  }
  const double length = s.xTrailing - s.xLeading;
  for (auto& q : loop)
    q = Eigen::Vector2d(s.xLeading + (q.x() - xmin) / (xmax - xmin) * length,
                        s.yLeading + q.y() * length);
  return loop;
}

// Distance of each point to a closed polyline (exact segment distances).
inline Deviation deviationFromPolyline(const std::vector<Eigen::Vector2d>& points,
                                       const std::vector<Eigen::Vector2d>& loop) {
  Deviation d;
  for (std::size_t i = 0; i < points.size(); ++i) {
    double best = std::numeric_limits<double>::max();
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Eigen::Vector2d a = loop[k], b = loop[(k + 1) % loop.size()];
      const double t = std::clamp((points[i] - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a + t * (b - a) - points[i]).squaredNorm());
    }
    best = std::sqrt(best);
    d.mean += best;
    if (best > d.max) {
      d.max = best;
      d.maxIndex = static_cast<int>(i);
    }
  }
  d.mean /= static_cast<double>(points.size());
  return d;
}

}  // namespace passageMesh::testData
