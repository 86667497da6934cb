// checkMeshQuality: the a-priori quality Q of the case's mesh (method.md section 5,
// docs/quality.md).
//   reads  mesh/passage.cgns
//   writes postProcessing/meshQuality.xml, mesh/passage.vtm (+ mesh/passage/*.vts) with the
//          cell fields QJ and QS
// Exit codes: 0 valid mesh, 2 invalid (folded) mesh, reported and written all the same
// with Q = -1, 1 unreadable input.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/quality/MeshQuality.hpp"
#include "passageMesh/quality/MeshQualityReport.hpp"
#include "passageMesh/structured/CgnsReader.hpp"
#include "passageMesh/structured/VtkWriter.hpp"

using namespace passageMesh;

namespace {

// VTK's ASCII reader takes no NaN or infinity (Q_J of a cell whose corners all have J = 0).
std::vector<std::vector<double>> finiteOrPenalty(std::vector<std::vector<double>> values) {
  for (auto& block : values)
    for (double& v : block)
      if (!std::isfinite(v)) v = invalidMeshQuality;
  return values;
}

}  // namespace

int main(int argc, char* argv[]) {
  return runUtility("checkMeshQuality", [&] {
    CommandLine cli("checkMeshQuality",
                    "Computes the a-priori mesh quality Q of mesh/passage.cgns (docs/quality.md),\n"
                    "writes postProcessing/meshQuality.xml and adds the cell fields QJ and QS to\n"
                    "mesh/passage.vtm. Exit code 2 for an invalid (folded) mesh.");
    if (!cli.parse(argc, argv)) return 0;
    const auto& dir = cli.caseDir();
    const auto cgnsFile = dir / "mesh" / "passage.cgns";
    const auto [mesh, quality] = readMeshWithQuality(cgnsFile);
    auto files = vtmFileContents(mesh, dir / "mesh" / "passage.vtm",
                                 {{"QJ", finiteOrPenalty(quality.cellQJ)},
                                  {"QS", finiteOrPenalty(quality.cellQS)}});
    files.emplace_back(dir / "postProcessing" / "meshQuality.xml",
                       formatMeshQualityXml(mesh, quality, "mesh/passage.cgns"));
    writeFilesAtomically(files);
    std::printf("checkMeshQuality: %s\n%s  wrote postProcessing/meshQuality.xml, mesh/passage.vtm\n",
                cgnsFile.string().c_str(), formatMeshQualitySummary(mesh, quality).c_str());
    if (quality.valid) return 0;
    std::cerr << "checkMeshQuality: INVALID MESH: " << quality.problem << " (Q = "
              << invalidMeshQuality << ")\n";
    return 2;
  });
}
