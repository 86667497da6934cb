#include "passageMesh/mesh/OuterLoop.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "passageMesh/mesh/ArcLengthTable.hpp"

namespace passageMesh {

namespace {

// Arc length of the lower periodic segment from xA (inlet interface), x as the parameter.
ArcLengthTable periodicArcLength(const PassageBoundary& b, int samples) {
  const double xA = b.inletInterfaceX(), xB = b.outletInterfaceX();
  std::vector<double> x(samples + 1);
  std::vector<Eigen::Vector2d> points(samples + 1);
  for (int k = 0; k <= samples; ++k) {
    x[k] = xA + (xB - xA) * k / samples;
    points[k] = Eigen::Vector2d(x[k], b.lowerY(x[k]));
  }
  return ArcLengthTable(std::move(x), points);
}

}  // namespace

std::vector<double> periodicArcPositions(double length, int intervals, double inletSpacing,
                                         double outletSpacing) {
  if (intervals < 1 || !(length > 0) || !(inletSpacing > 0) || !(outletSpacing > 0))
    throw std::invalid_argument("periodicArcPositions: need intervals >= 1 and positive lengths");
  // s(xi) = L xi + c0 xi (1 - xi)^m - c1 xi^m (1 - xi): s'(0) = L + c0, s'(1) = L + c1, so
  // the end intervals are about the wanted spacings, and the corrections fade within about
  // 1/m of the segment. |c| <= L keeps s' > 0: the correction terms' slopes dip to -0.17
  // at most for m = 8.
  constexpr int m = 8;
  const double c0 = std::clamp(inletSpacing * intervals - length, -length, length);
  const double c1 = std::clamp(outletSpacing * intervals - length, -length, length);
  std::vector<double> s(static_cast<std::size_t>(intervals) + 1);
  for (int k = 0; k <= intervals; ++k) {
    const double xi = static_cast<double>(k) / intervals;
    s[k] = length * xi + c0 * xi * std::pow(1 - xi, m) - c1 * std::pow(xi, m) * (1 - xi);
  }
  s.front() = 0;
  s.back() = length;
  return s;
}

OuterLoop buildOuterLoop(const PassageBoundary& boundary, int nT, int lowerSideIntervals,
                         double leadingEdgeY, double trailingEdgeY, double splitIn,
                         double splitOut) {
  const double xA = boundary.inletInterfaceX(), xB = boundary.outletInterfaceX();
  const double pitch = boundary.pitch();
  const double yLowA = boundary.lowerY(xA), yLowB = boundary.lowerY(xB);
  const ArcLengthTable arc = periodicArcLength(boundary, 2000);
  // The splits: where the edges face the interfaces, kept a tenth of the pitch inside
  // them, then moved as asked and kept a hundredth inside (each piece keeps a node).
  const double margin = 0.1 * pitch, splitMargin = 0.01 * pitch;
  const double yMid = std::clamp(std::clamp(leadingEdgeY, yLowA + margin, yLowA + pitch - margin) + splitIn * pitch,
                                 yLowA + splitMargin, yLowA + pitch - splitMargin);
  const double ySeam = std::clamp(std::clamp(trailingEdgeY, yLowB + margin, yLowB + pitch - margin) + splitOut * pitch,
                                  yLowB + splitMargin, yLowB + pitch - splitMargin);

  const int upperSideIntervals = nT - lowerSideIntervals;
  // The interface pieces' lengths on each side of the loop (the periodic segments have the
  // same length).
  const double lowerOut = ySeam - yLowB, lowerIn = yMid - yLowA;
  const double upperIn = yLowA + pitch - yMid, upperOut = yLowB + pitch - ySeam;
  // Both periodic segments need one count: the mean of the two sides' shares by length,
  // rounded once; each side's rest is split between its interface pieces by their lengths.
  // Every count is then a rounded linear function of the sides' intervals and moves by at
  // most one node when nT does. (Rounding each side's three shares and taking the mean of
  // the two periodic ones made the counts step back and forth with nT, and Q with them:
  // docs/elliptic-smoothing.md "Outer-loop counts rounded once".)
  OuterLoop loop;
  const double lowerShare = lowerSideIntervals * arc.length() / (lowerOut + arc.length() + lowerIn);
  const double upperShare = upperSideIntervals * arc.length() / (upperIn + arc.length() + upperOut);
  loop.periodic = std::max(2, static_cast<int>(std::lround(0.5 * (lowerShare + upperShare))));
  const int lowerRest = lowerSideIntervals - loop.periodic, upperRest = upperSideIntervals - loop.periodic;
  loop.outletLower = static_cast<int>(std::lround(lowerRest * lowerOut / (lowerOut + lowerIn)));
  loop.inletLower = lowerRest - loop.outletLower;
  loop.inletUpper = static_cast<int>(std::lround(upperRest * upperIn / (upperIn + upperOut)));
  loop.outletUpper = upperRest - loop.inletUpper;
  auto fix = [](int& a, int& b) {  // keep both of a pair of pieces >= 1
    if (a < 1) { b -= 1 - a; a = 1; }
    if (b < 1) { a -= 1 - b; b = 1; }
  };
  fix(loop.outletLower, loop.inletLower);
  fix(loop.inletUpper, loop.outletUpper);
  if (loop.outletLower < 1 || loop.inletLower < 1 || loop.inletUpper < 1 || loop.outletUpper < 1)
    throw std::invalid_argument("outer loop: too few nodes for the pieces of the boundary");

  // Interfaces uniform in y over the whole pitch: the seam and the inlet split move to the
  // node the counts give them.
  const double dyOut = pitch / (loop.outletLower + loop.outletUpper);
  const double dyIn = pitch / (loop.inletLower + loop.inletUpper);
  auto& p = loop.nodes;
  p.reserve(nT);
  for (int k = 0; k < loop.outletLower; ++k)  // seam down to the lower outlet corner
    p.emplace_back(xB, yLowB + (loop.outletLower - k) * dyOut);
  std::vector<double> periodicX(loop.periodic + 1);
  const auto periodicArc = periodicArcPositions(arc.length(), loop.periodic, dyIn, dyOut);
  for (int k = 0; k <= loop.periodic; ++k)
    periodicX[k] = k == 0 ? xA : (k == loop.periodic ? xB : arc.parameterAt(periodicArc[k]));
  for (int k = loop.periodic; k > 0; --k)  // lower periodic, xB to xA (corner at xA next)
    p.emplace_back(periodicX[k], boundary.lowerY(periodicX[k]));
  for (int k = 0; k < loop.inletLower + loop.inletUpper; ++k)  // inlet, bottom to top
    p.emplace_back(xA, yLowA + k * dyIn);
  for (int k = 0; k < loop.periodic; ++k)  // upper periodic, xA to xB
    p.emplace_back(periodicX[k], boundary.upperY(periodicX[k]));
  for (int k = 0; k < loop.outletUpper; ++k)  // outlet, top down to just above the seam
    p.emplace_back(xB, yLowB + pitch - k * dyOut);
  if (static_cast<int>(p.size()) != nT)
    throw std::logic_error("outer loop: node count mismatch");
  return loop;
}

}  // namespace passageMesh
