#pragma once
// The O-block's outer boundary (method.md section 4): the closed loop made of the inlet
// interface, the upper periodic segment, the outlet interface and the lower periodic
// segment, carrying as many nodes as the blade loop, in the same (clockwise) order.
//
// Node i of the loop faces blade node i. The loop starts at the seam on the outlet
// interface (facing the trailing edge) and runs down it, leftwards along the lower
// periodic segment, up the inlet interface, rightwards along the upper periodic segment
// and down the outlet interface back to the seam:
//
//   piece      nodes (i)                          intervals
//   outlet low  0 .. a                            a   = outletLower
//   lower per.  a .. b                            nP  = periodic
//   inlet       b .. c                            inletLower + inletUpper
//   upper per.  c .. d                            nP
//   outlet up   d .. nT (= node 0 again)          outletUpper
//
// The counts share the blade's: the lower side's nodes face outlet-low, the lower periodic
// segment and the inlet interface's lower part, the upper side's nodes the rest. Where the
// two sides meet on each interface (the split) is the edge's height, kept a tenth of the
// pitch inside the periodic boundaries, moved by splitIn / splitOut pitches (and then kept
// a hundredth of the pitch inside); the counts are in
// proportion to the pieces' lengths (the periodic count the mean of both sides' shares,
// rounded once; each side's interface pieces split the rest). Both periodic segments
// carry the same count and the same x values, bit for bit: y_upper = y_lower + pitch.
// Interface nodes are uniform in y (the H-blocks beyond them have uniform cells);
// periodic nodes uniform in arc length
// except near the two corners, where their spacing grows or shrinks to the interface's
// (periodicArcPositions): the cells at a corner are then as large on both of its sides
// whatever the counts, so one node more on an interface no longer jumps Q_J there.
#include <Eigen/Core>
#include <vector>

#include "passageMesh/passage/PassageBoundary.hpp"

namespace passageMesh {

struct OuterLoop {
  std::vector<Eigen::Vector2d> nodes;  // nT nodes, clockwise from the seam
  int outletLower = 0, periodic = 0, inletLower = 0, inletUpper = 0, outletUpper = 0;

  int lowerPeriodicBegin() const { return outletLower; }
  int lowerPeriodicEnd() const { return outletLower + periodic; }  // inlet corner
  int upperPeriodicBegin() const { return lowerPeriodicEnd() + inletLower + inletUpper; }
  int upperPeriodicEnd() const { return upperPeriodicBegin() + periodic; }  // outlet corner
};

// Arc-length positions s_0 = 0 < s_1 < ... < s_intervals = length of the periodic nodes
// from the inlet corner: uniform in the middle, the first interval about `inletSpacing`
// and the last about `outletSpacing` (the interfaces' node spacings), blended in smoothly
// over the eighth of the segment next to each corner (docs/elliptic-smoothing.md).
std::vector<double> periodicArcPositions(double length, int intervals, double inletSpacing,
                                         double outletSpacing);

// `lowerSideIntervals`: the blade nodes from the trailing edge (i = 0) to the leading edge
// (i = lowerSideIntervals); `nT` nodes in all. `splitIn`, `splitOut`: the splits' moves
// in pitches (MeshingParameters). Throws std::invalid_argument when a piece would get no
// interval.
OuterLoop buildOuterLoop(const PassageBoundary& boundary, int nT, int lowerSideIntervals,
                         double leadingEdgeY, double trailingEdgeY, double splitIn = 0,
                         double splitOut = 0);

}  // namespace passageMesh
