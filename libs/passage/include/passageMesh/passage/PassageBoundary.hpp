#pragma once
// The periodic passage boundary and the O/H block interfaces (method.md section 3).
//
// The leading and trailing edge are the camber line's end points (xLe, yLe) and its
// trailing-edge point; y_camber(x) is the camber line. The lower periodic boundary is
//   y_le + yIn - pitch/2                       upstream of the leading edge,
//   a y_c(x) + (1 - a) y_l(x)                  along the blade (a = alphaCamber),
//   y_te + yOut - pitch/2                      downstream of the trailing edge,
// with y_l the straight line between the two end values and
//   y_c(x) = y_camber(x) + yIn s(x) + yOut (1 - s(x)) - pitch/2,
// which is the paper's formula when s = (y_camber - y_te) / (y_le - y_te). That s is
// undefined for y_le = y_te (an impulse blade such as SIRT), so s blends it smoothly with
// the linear s_x = (x_te - x) / (x_te - x_le):
//   s = w s_paper + (1 - w) s_x,  w = D^2 / (D^2 + d^2),  D = y_le - y_te,  d = 0.05 chord,
// written as w s_paper = D (y_camber - y_te) / (D^2 + d^2), which stays finite. For
// |D| >> d it is the paper's formula; at both edges s is exactly 1 and 0, so the boundary
// is continuous. The upper boundary is the lower one plus the pitch.
//
// Departure from the paper (2026-12-02): that curve has a slope kink at x_le and at x_te,
// where the flat parts meet the camber-following part. At each kink, where it opens into
// the O-block, the grid lines reach the boundary at a grazing angle: the worst cells of the
// tutorials and many folds of the robustness sweep sat there (docs/elliptic-smoothing.md).
// Each kink is therefore replaced by a fillet from x_k - d to x_k + d: the cubic Hermite
// curve with the paper's values and slopes at both window ends. The boundary is C1 and
// moves continuously with the parameters. Where the pieces are straight, the fillet is
// the parabola tangent to both, on the concave side of the kink.
// d = min(0.2 chord, half the distance from the edge to its interface, a quarter of the
// axial chord). So the boundary stays flat at the interfaces, where the corners of the
// outer loop stay at 90 degrees.
#include <Eigen/Core>

#include "passageMesh/blade/BladeShape.hpp"
#include "passageMesh/passage/MeshingParameters.hpp"
#include "passageMesh/passage/PassageCondition.hpp"

namespace passageMesh {

class PassageBoundary {
 public:
  PassageBoundary(const BladeShape& blade, const PassageCondition& condition,
                  const MeshingParameters& parameters);

  double inletX() const { return le_.x() - condition_.xIn; }
  double outletX() const { return te_.x() + condition_.xOut; }
  double inletInterfaceX() const { return le_.x() - parameters_.betaIn * condition_.xIn; }
  double outletInterfaceX() const { return te_.x() + parameters_.betaOut * condition_.xOut; }
  double pitch() const { return condition_.pitch; }

  double lowerY(double x) const;
  double upperY(double x) const { return lowerY(x) + condition_.pitch; }

 private:
  // The cubic Hermite y(x) over [x0, x1] with values y0, y1 and slopes slope0, slope1 at
  // its ends; empty when x0 == x1.
  struct Fillet {
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0, slope0 = 0, slope1 = 0;
    bool covers(double x) const { return x1 > x0 && x > x0 && x < x1; }
    double y(double x) const;
  };
  double pieceY(double x) const;  // the paper's curve, kinks included
  Fillet filletAt(double xKink, double halfWidth) const;

  const BladeShape& blade_;
  PassageCondition condition_;
  MeshingParameters parameters_;
  Eigen::Vector2d le_, te_;
  Fillet leadingFillet_, trailingFillet_;
};

// The smallest distance [m] between the blade and the O-block's outer loop (the inlet and
// outlet interfaces and the periodic boundaries between them): how much room the O-block
// has. Zero or below when the loop touches or cuts the blade (then no mesh exists); a few
// per cent of the chord make a mesh very hard (docs/benchmarks.md, robustness sweep).
// Blade and loop sampled at 400 points a side and a piece: the error is below the
// distance between neighbouring loop samples.
double bladeClearance(const BladeShape& blade, const PassageBoundary& boundary);

// The widest extent in y of the blade at one x, and that x [m]. The periodic boundaries
// are curves y(x) a pitch apart with the blade between them, so a passage exists only
// where the pitch exceeds this; at a pitch at or below it the blade overlaps its periodic
// neighbour (a cascade that cannot exist), and no choice of meshing parameters helps.
// From the profile sampled at 2000 points, cut at the x of every fourth sample (about
// 2 ms): the result may fall short of the true widest extent and exceeds it by at most the
// polygon's sagitta (below 1e-6 chord), so a pitch it refuses is too small to within that.
// (Where a vertical line meets the blade in one interval, as on the usual profiles, the
// blade then overlaps its periodic neighbour; in any case no boundary y(x) fits.)
struct BladeYExtent {
  double extent = 0;  // [m]
  double x = 0;       // [m]
};
BladeYExtent widestYExtent(const BladeShape& blade);

}  // namespace passageMesh
