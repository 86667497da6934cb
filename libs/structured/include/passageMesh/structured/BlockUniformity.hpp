#pragma once
// How far a block is from uniform cells (the H-blocks of an HOH mesh must be uniform).
#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

// Largest relative deviation of any cell edge of the block from the mean edge length in
// its direction (0 for a perfectly uniform block).
double blockNonUniformity(const StructuredBlock& block);

}  // namespace passageMesh
