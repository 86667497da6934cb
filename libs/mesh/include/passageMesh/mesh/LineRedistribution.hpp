#pragma once
// The O-block's final nodes from a smoothed grid with few rows (docs/elliptic-smoothing.md):
// the elliptic equations are solved on rows spaced evenly along each line, where the
// lines' bending is spread over physical distance; the wall clustering is applied
// afterwards by placing the final rows along each smoothed j-line (a Catmull-Rom curve
// through its nodes, by arc length), so the near-wall cells inherit the smoothed line's
// direction instead of taking the bend in a few thin cells.
#include <Eigen/Core>
#include <vector>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

// Fills rows 1 .. target.nj - 1 of `target` (ni as `lines`, the seam column repeated; row 0
// is copied from `lines`) along the j-lines of `lines`: distances from the wall by
// wallClusteredDistances with first spacing `firstSpacing`, the last spacing moved 90 % of
// the way to the outer loop's node spacing there (moveLastSpacing: nearly square cells at
// the outer loop, matching the H-blocks and the periodic images). The last row is `lines`' outer row exactly.
// Near the wall the nodes are pulled onto the straight line along `wallNormals[i]`
// (unit, one per loop node): row 1 exactly, then less and less up to a distance L of
// `blendLength` times the wall node spacing there (at least 20 firstSpacing): the first
// cell height is exactly `firstSpacing` along the normal and the lines leave the wall
// orthogonally, then turn smoothly into the smoothed lines. The pull is a smoothstep in
// log(d / firstSpacing) / log(L / firstSpacing), d the distance from the wall: the
// wall-clustered rows grow about geometrically, so the turn is spread evenly over the
// rows of the blend instead of being taken in its last few (docs/elliptic-smoothing.md).
// Empty `wallNormals`: no blend. `firstRowDirections` (unit, one per wall normal; empty:
// the wall normals): row 1 alone along these instead, at firstSpacing from the wall; the
// rows above blend from the wall normals as before.
// Throws std::invalid_argument when a line is too short for the first spacing, or when the
// directions do not match the loop.
void redistributeAlongLines(const StructuredBlock& lines, StructuredBlock& target,
                            double firstSpacing,
                            const std::vector<Eigen::Vector2d>& wallNormals = {},
                            double blendLength = 3.0,
                            const std::vector<Eigen::Vector2d>& firstRowDirections = {});

}  // namespace passageMesh
