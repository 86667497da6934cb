// exportMesh: the case's mesh in the formats RANS solvers read (MeshExport.hpp).
//   reads  mesh/passage.cgns
//   writes constant/polyMesh/ (foam), mesh/passage.xyz (plot3d),
//          mesh/passageSU2.cgns + mesh/passageSU2.cfg (su2cgns); all together or none
#include <cstdio>
#include <stdexcept>
#include <string>

#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/structured/CgnsReader.hpp"
#include "passageMesh/meshExport/MeshExport.hpp"

using namespace passageMesh;
namespace po = boost::program_options;

int main(int argc, char* argv[]) {
  return runUtility("exportMesh", [&] {
    CommandLine cli("exportMesh",
                    "Writes mesh/passage.cgns in solver formats: foam (constant/polyMesh, one\n"
                    "cell thick, cyclic periodic patches), plot3d (mesh/passage.xyz), su2cgns\n"
                    "(mesh/passageSU2.cgns + .cfg). Formats are written together or not at all.");
    cli.addOptions()("format", po::value<std::string>()->default_value("foam"),
                     "comma-separated formats: foam, plot3d, su2cgns");
    if (!cli.parse(argc, argv)) return 0;
    const auto formats = parseExportFormats(cli.values()["format"].as<std::string>());
    const auto cgnsFile = cli.caseDir() / "mesh" / "passage.cgns";
    const StructuredMesh mesh = readCgns(cgnsFile);
    std::vector<std::filesystem::path> written;
    try {
      written = exportMesh(mesh, cli.caseDir(), formats);
    } catch (const std::invalid_argument& e) {
      throw InputError(cgnsFile.string(), 0, e.what());
    }
    std::printf("exportMesh: %s\n", cgnsFile.string().c_str());
    for (const auto& p : written) std::printf("  wrote %s\n", p.string().c_str());
    return 0;
  });
}
