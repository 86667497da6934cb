#pragma once
// Multi-block Plot3D, whole-grid 3-D form (no iblank), ASCII: the structured blocks
// extruded one cell thick in z, as OpenFOAM's plot3dToFoam and most structured solvers
// read it (docs/case-format.md):
//   nBlocks
//   ni nj 2          one line per block
//   x of block 1 (i fastest, then j, then k), then its y, then its z; then block 2, ...
// Values with 17 significant digits, five per line. Block interfaces are not merged:
// the reader matches coincident nodes.
#include <string>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

std::string plot3dAscii(const StructuredMesh& mesh, double thickness);

// The same grid as Fortran unformatted sequential records (what NASA's Plot3D readers and
// most structured solvers call "binary"), little-endian whatever the host: each record is
// framed by its byte count as a 32-bit integer before and after it. Records: the block
// count (int32); ni, nj, 2 of every block (int32); then one record per block holding its
// x, y and z (float64, in the order of the ASCII form).
std::string plot3dBinary(const StructuredMesh& mesh, double thickness);

}  // namespace passageMesh
