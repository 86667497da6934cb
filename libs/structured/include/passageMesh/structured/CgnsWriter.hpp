#pragma once
// Writes a StructuredMesh as CGNS (HDF5), the input RANS solvers read.
//
// Layout: one base "Base" (CellDimension = PhysicalDimension = 2, Dimensional, SI units),
// one structured zone per block named by the block, in block order, with CoordinateX/Y
// (RealDouble). CGNS indices are 1-based: mesh node (i, j) is CGNS point (i + 1, j + 1).
//
// Connections: each BlockConnection becomes a GridConnectivity1to1_t in both zones, named
// `name` in zone a and, in zone b, `name` again (or `name` + "_reverse" when a block is
// joined to itself, since both entries then live in the same zone). In every entry the
// zone's own PointRange ascends; the donor range keeps the node-to-node pairing. The
// transform maps each index direction of the zone to the donor's: along the face by the
// directions the two ranges run, across it so that leaving the zone enters the donor.
// Periodic connections carry Periodic_t (zero rotation, translation +t in zone a, -t in
// zone b; CGNS stores these as single precision).
//
// Patches: each BoundaryPatch becomes a BC_t (PointRange, ascending) of type BCWall,
// BCInflow or BCOutflow with a FamilyName naming a Family_t "patch name" in the base
// (with the same FamilyBC). Patches sharing a name share the family and must share the
// type; a second patch of that name in the same zone is written as "name_2", etc.
#include <filesystem>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

// Throws std::invalid_argument when the mesh is inconsistent: a block with fewer than
// 2 x 2 nodes or wrongly sized coordinate arrays, a non-finite coordinate, duplicate or
// over-long (> 32 characters) names, a range not on a block edge or of fewer than two
// nodes, connected ranges of different node counts or whose nodes do not coincide
// (within 1e-6 of the mesh size, after the translation). Throws std::runtime_error
// naming the file (and the CGNS error) when the file cannot be written. The file is
// written to a temporary beside it and renamed, so a failure leaves no partial file.
// Not thread-safe: the CGNS library has global state.
void writeCgns(const StructuredMesh& mesh, const std::filesystem::path& file);

// What writeCgns writes, as a FileWriter for a tool that writes the CGNS file together
// with its other outputs (writeFilesAtomically). Checks the mesh now (same exceptions);
// the mesh must outlive the writer.
FileWriter cgnsFileWriter(const StructuredMesh& mesh, const std::filesystem::path& file);
// The writer keeps a reference: a temporary mesh would be gone before it writes.
FileWriter cgnsFileWriter(const StructuredMesh&& mesh, const std::filesystem::path& file) = delete;

// The checks writeCgns makes before it writes anything (same exceptions).
void validateStructuredMesh(const StructuredMesh& mesh);

}  // namespace passageMesh
