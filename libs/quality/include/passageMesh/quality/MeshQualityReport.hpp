#pragma once
// What checkMeshQuality writes: postProcessing/meshQuality.xml (format in
// docs/case-format.md) and a one-screen summary for the terminal.
#include <filesystem>
#include <string>

#include "passageMesh/quality/MeshQuality.hpp"
#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

// The XML document: values with 17 significant digits, block names for cell locations.
// `source` (e.g. "mesh/passage.cgns") is recorded as an attribute.
std::string formatMeshQualityXml(const StructuredMesh& mesh, const MeshQuality& quality,
                                 const std::string& source);

// A few lines: Q and its four parts, validity (loudly when invalid), the worst cells, and
// the other blocks' statistics when `quality.blocks` is filled.
std::string formatMeshQualitySummary(const StructuredMesh& mesh, const MeshQuality& quality);

// A case's mesh read back from CGNS with its quality (MeshQualityOptions::everyBlock), as
// checkMeshQuality and plotMesh need it. A file the CGNS reader refuses, or a mesh the
// quality cannot be computed on, is an InputError naming the file.
struct MeshWithQuality {
  StructuredMesh mesh;
  MeshQuality quality;
};
MeshWithQuality readMeshWithQuality(const std::filesystem::path& cgnsFile);

}  // namespace passageMesh
