#pragma once
// exportMesh's work: the case's mesh in the formats solvers read (docs/case-format.md).
//   foam     constant/polyMesh/ (FoamPolyMesh.hpp), replaced whole
//   plot3d   mesh/passage.xyz (ASCII) and mesh/passage.x (binary) (Plot3dFile.hpp)
//   su2cgns  mesh/passageSU2.cgns and mesh/passageSU2.cfg (Su2Cgns.hpp)
// Every format is written to temporaries first and all are moved into place together
// (StagedOutputs), so a failure leaves the case as it was.
#include <filesystem>
#include <string>
#include <vector>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

enum class ExportFormat { foam, plot3d, su2cgns };

// "foam,plot3d": each name once, in the given order. Throws InputError for an empty list,
// an unknown or repeated name.
std::vector<ExportFormat> parseExportFormats(const std::string& list);

// Writes the formats for the mesh into `caseDir`; returns the paths written (relative to
// the case). The one-cell extrusion is foamThicknessChords of the chord (BladeEdges) thick.
// Throws std::invalid_argument for a mesh that is not a closed passage
// (makeUnstructuredPassage), std::runtime_error naming the target when one cannot be
// written.
std::vector<std::filesystem::path> exportMesh(const StructuredMesh& mesh,
                                              const std::filesystem::path& caseDir,
                                              const std::vector<ExportFormat>& formats);

}  // namespace passageMesh
