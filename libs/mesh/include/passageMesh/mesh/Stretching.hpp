#pragma once
// Node clustering functions of the mesher: maps of [0, 1] onto itself.
#include <vector>

namespace passageMesh {

// One-sided hyperbolic-tangent clustering towards xi = 0 with strength gamma >= 0:
//   1 - tanh(gamma (1 - xi)) / tanh(gamma);   gamma -> 0 gives xi (uniform).
double tanhClusterStart(double xi, double gamma);
// The same towards xi = 1:  tanh(gamma xi) / tanh(gamma).
double tanhClusterEnd(double xi, double gamma);

// Two-sided clustering with independent strengths at the two ends, used for the blade
// nodes (gammaLE, gammaTE):
//   f(xi) = (1 - w) tanhClusterStart(xi, gammaStart) + w tanhClusterEnd(xi, gammaEnd),
//   w = xi^2 (3 - 2 xi).
// It is strictly increasing for all strengths (tanhClusterStart <= xi <= tanhClusterEnd,
// both increasing, w increasing), f(0) = 0, f(1) = 1. Since w and 1 - w vanish
// quadratically at the ends, the spacing next to each end is set by that end's gamma
// (the other gamma changes it by O(h^2) relative for spacing h) and shrinks
// monotonically as that gamma grows. gamma = 0 at both ends is uniform.
double tanhStretch(double xi, double gammaStart, double gammaEnd);

// Distances 0 = s_0 < s_1 < ... < s_{n-1} = length of n nodes along a wall-normal line,
// clustered towards the wall by tanhClusterStart with the strength that makes the first
// spacing s_1 exactly `firstSpacing` (to round-off). Throws std::invalid_argument when
// that is impossible: firstSpacing >= length / (n - 1) would need stretching away from the
// wall, n < 2, or non-positive lengths.
std::vector<double> wallClusteredDistances(int n, double length, double firstSpacing);

// Moves the last spacing of increasing distances s_0 .. s_m (m >= 2) to `lastSpacing`,
// keeping both ends: c t^8 (t - 1), t = j / m, is added to each, c chosen so the last
// spacing becomes `lastSpacing`, clipped where a spacing would fall to half of what it
// was (continuous in the arguments: no node jumps). t^8 leaves the first spacing exact (to
// round-off) and the wall half of a line unchanged; LineRedistribution uses it to match
// the cells beyond the outer loop (the H-blocks and the periodic images).
void moveLastSpacing(std::vector<double>& distances, double lastSpacing);

// The clustering strength wallClusteredDistances uses.
double wallClusteringStrength(int n, double length, double firstSpacing);

}  // namespace passageMesh
