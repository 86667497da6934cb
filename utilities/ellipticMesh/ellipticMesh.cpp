// ellipticMesh: the HOH passage mesh (method.md section 4).
//   reads  constant/bladeParameters.xml, system/passageDict.xml,
//          system/meshDict.xml (optional: missing keys take etc/meshDictDefaults.xml)
//   writes mesh/passage.cgns, mesh/passage.vtm + mesh/passage/<block>.vts
// An invalid (folded) mesh is an error: nothing is written.
#include <cstdio>
#include <filesystem>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/mesh/MeshStatistics.hpp"
#include "passageMesh/passage/PassageCase.hpp"
#include "passageMesh/structured/CgnsWriter.hpp"
#include "passageMesh/structured/VtkWriter.hpp"

using namespace passageMesh;

int main(int argc, char* argv[]) {
  return runUtility("ellipticMesh", [&] {
    CommandLine cli("ellipticMesh",
                    "Builds the HOH mesh of the case's blade passage (H-block inlet, elliptic\n"
                    "O-block, H-block outlet) and writes mesh/passage.cgns and mesh/passage.vtm.");
    if (!cli.parse(argc, argv)) return 0;
    const PassageCase input = readPassageCase(cli.caseDir(), "ellipticMesh");
    const auto& dir = cli.caseDir();
    const PassageCondition& condition = input.condition;
    const MeshingParameters& parameters = input.parameters;

    const HohMesh hoh = buildHohMesh(input.blade, condition, parameters);
    const EllipticReport& s = hoh.smoothing;
    if (s.iterations > 0)
      std::printf("ellipticMesh: O-block %d x %d nodes; elliptic smoothing: %d multigrid cycles, "
                  "residual %.3e (%s)\n", parameters.nT, hoh.nN, s.iterations, s.residual,
                  s.converged ? "converged" : "NOT converged");
    else  // refused before smoothing (a boundary through the blade, an impossible clustering),
          // or too few rows to smooth
      std::printf("ellipticMesh: O-block %d x %d nodes; not smoothed\n", parameters.nT, hoh.nN);
    if (!hoh.valid) throw std::runtime_error("the mesh is invalid: " + hoh.problem);

    const StructuredBlock& o = hoh.mesh.blocks[1];
    const WallLayerStatistics wall = wallLayerStatistics(o, condition.firstCellHeight);
    std::printf("  first cell height within 2 %% at %.1f %% of the wall nodes (worst %.2f %% at "
                "i = %d)\n  wall-line angle: mean deviation from 90 deg %.3f deg, max %.3f deg "
                "at i = %d\n  H-block cell non-uniformity: inlet %.2e, outlet %.2e\n",
                100 * wall.heightWithin2Percent, 100 * wall.heightMaxError, wall.heightWorstNode,
                wall.angleMeanDeviation, wall.angleMaxDeviation, wall.angleWorstNode,
                blockNonUniformity(hoh.mesh.blocks[0]), blockNonUniformity(hoh.mesh.blocks[2]));

    validateStructuredMesh(hoh.mesh);
    std::filesystem::create_directories(dir / "mesh");
    writeFilesAtomically(vtmFileContents(hoh.mesh, dir / "mesh" / "passage.vtm"));
    writeCgns(hoh.mesh, dir / "mesh" / "passage.cgns");
    std::printf("  wrote mesh/passage.cgns, mesh/passage.vtm\n");
    return 0;
  });
}
