#pragma once
// An OpenFOAM constant/polyMesh (points, faces, owner, neighbour, boundary; ASCII, 17
// significant digits) of the passage extruded one cell thick in z, the 2-D form OpenFOAM
// solves on (docs/case-format.md).
//
// Points: the 2-D points at z = 0, then the same at z = thickness. Faces: the internal
// edges extruded (owner < neighbour, ordered by owner then neighbour), then each patch's
// edges extruded, patch by patch in UnstructuredPassage's order, then the frontAndBack
// faces (every cell at z = 0, then at z = thickness). Every face's normal points out of
// its owner. Patches: wall patches as `wall`, inlet and outlet as `patch`, the periodic
// pair as translational `cyclic` patches (face k of periodicLower matches face k of
// periodicUpper; separationVector lower -> upper), frontAndBack `empty`.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "passageMesh/meshExport/UnstructuredPassage.hpp"

namespace passageMesh {

// The z thickness exportMesh gives the one-cell extrusion: a hundredth of the chord.
inline constexpr double foamThicknessChords = 0.01;

// The five files, each name (e.g. "points") with its content.
std::vector<std::pair<std::string, std::string>> foamPolyMeshFiles(const UnstructuredPassage& passage,
                                                                   double thickness);

// Writes the five files into `directory` (which must exist). Throws std::runtime_error
// naming the file when one cannot be written.
void writeFoamPolyMesh(const UnstructuredPassage& passage, double thickness,
                       const std::filesystem::path& directory);

}  // namespace passageMesh
