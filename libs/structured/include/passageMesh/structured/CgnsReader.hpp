#pragma once
// Reads back what writeCgns writes (CgnsWriter.hpp has the layout) as a StructuredMesh,
// e.g. mesh/passage.cgns for checkMeshQuality.
//
// - Blocks: the structured zones of the first base, with CoordinateX/Y, in the order they
//   were written (the file's creation order; the CGNS library itself lists them by name).
// - Connections: each pair of GridConnectivity1to1_t entries (one in each zone, the second
//   named like the first, or with "_reverse" for a block joined to itself) becomes one
//   BlockConnection; an entry without a partner becomes one too. Side a is the entry read
//   first (for a self-connection the one without "_reverse"); node k of the PointRange
//   pairs with node k of the DonorRange (the Transform is not needed for that). A periodic
//   entry's translation is stored in single precision, so the reader takes it from the
//   coordinates of the first node pair, in double, after checking it agrees with the
//   stored one (to 1e-6 of its length).
// - Patches: each BC_t (PointRange) becomes a BoundaryPatch named by its FamilyName (or by
//   the BC name when it has none), typed from BCWall*, BCInflow*, BCOutflow* or the
//   family's FamilyBC.
// The result passes validateStructuredMesh.
#include <filesystem>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

// Throws InputError naming the file and what was expected when the file is missing, is
// not CGNS, or does not hold a 2-D structured multi-block mesh of this form. Not
// thread-safe: the CGNS library has global state.
StructuredMesh readCgns(const std::filesystem::path& file);

}  // namespace passageMesh
