#include "passageMesh/meshExport/MeshExport.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/StagedOutputs.hpp"
#include "passageMesh/meshExport/BladeEdges.hpp"
#include "passageMesh/meshExport/FoamPolyMesh.hpp"
#include "passageMesh/meshExport/Plot3dFile.hpp"
#include "passageMesh/meshExport/Su2Cgns.hpp"

namespace passageMesh {

namespace fs = std::filesystem;

std::vector<ExportFormat> parseExportFormats(const std::string& list) {
  std::vector<ExportFormat> formats;
  // A trailing comma would end getline's split silently: refuse it as an empty name.
  std::stringstream names(list + (list.empty() || list.back() == ',' ? "," : ""));
  for (std::string name; std::getline(names, name, ',');) {
    if (name.empty()) throw InputError("-format: an empty format name in '" + list + "'");
    ExportFormat f;
    if (name == "foam") f = ExportFormat::foam;
    else if (name == "plot3d") f = ExportFormat::plot3d;
    else if (name == "su2cgns") f = ExportFormat::su2cgns;
    else throw InputError("-format: unknown format '" + name + "' (known: foam, plot3d, su2cgns)");
    if (std::find(formats.begin(), formats.end(), f) != formats.end())
      throw InputError("-format: '" + name + "' given twice");
    formats.push_back(f);
  }
  if (formats.empty()) throw InputError("-format: no format given (known: foam, plot3d, su2cgns)");
  return formats;
}

std::vector<fs::path> exportMesh(const StructuredMesh& mesh, const fs::path& caseDir,
                                 const std::vector<ExportFormat>& formats) {
  const double thickness = foamThicknessChords * findBladeEdges(mesh).chord;
  const UnstructuredPassage passage = makeUnstructuredPassage(mesh);
  StagedOutputs staged;
  std::vector<fs::path> written;
  for (const ExportFormat f : formats) {
    switch (f) {
      case ExportFormat::foam: {
        const fs::path target = fs::path("constant") / "polyMesh";
        writeFoamPolyMesh(passage, thickness, staged.stage(caseDir / target, true));
        written.push_back(target);
        break;
      }
      case ExportFormat::plot3d: {
        const fs::path ascii = fs::path("mesh") / "passage.xyz", binary = fs::path("mesh") / "passage.x";
        staged.writeFile(caseDir / ascii, plot3dAscii(mesh, thickness));
        staged.writeFile(caseDir / binary, plot3dBinary(mesh, thickness));
        written.insert(written.end(), {ascii, binary});
        break;
      }
      case ExportFormat::su2cgns: {
        const fs::path su2Mesh = fs::path("mesh") / "passageSU2.cgns", config = fs::path("mesh") / "passageSU2.cfg";
        staged.write(su2CgnsFileWriter(passage, caseDir / su2Mesh));
        staged.writeFile(caseDir / config, su2ConfigFragment(passage, su2Mesh.filename().string()));
        written.insert(written.end(), {su2Mesh, config});
        break;
      }
    }
  }
  staged.commit();
  return written;
}

}  // namespace passageMesh
