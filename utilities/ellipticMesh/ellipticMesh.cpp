// ellipticMesh: the HOH passage mesh (method.md section 4).
//   reads  constant/bladeParameters.xml, system/passageDict.xml,
//          system/meshDict.xml (optional: missing keys take etc/meshDictDefaults.xml)
//   writes mesh/passage.cgns, mesh/passage.vtm + mesh/passage/<block>.vts
// An invalid (folded) mesh is an error: nothing is written. -polish: the O-block's final
// polish by optimisation (OBlockPolish.hpp; half a minute to a minute and a half at nO =
// 30000); Ctrl-C ends it early, the mesh is written with the polish so far and the exit
// code is 130.
#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/core/InterruptFlag.hpp"
#include "passageMesh/passage/PassageCase.hpp"
#include "passageMesh/workflow/PassageMeshFiles.hpp"

using namespace passageMesh;

int main(int argc, char* argv[]) {
  return runUtility("ellipticMesh", [&] {
    CommandLine cli("ellipticMesh",
                    "Builds the HOH mesh of the case's blade passage (H-block inlet, elliptic\n"
                    "O-block, H-block outlet) and writes mesh/passage.cgns and mesh/passage.vtm.");
    cli.addOptions()("polish", polishOptionHelp);
    if (!cli.parse(argc, argv)) return 0;
    const bool polish = cli.values().count("polish") > 0;
    const std::atomic<bool>* stop = polish ? &installInterruptFlag() : nullptr;
    const MeshedCase meshed =
        meshCaseAndWrite(readPassageCase(cli.caseDir(), "ellipticMesh"), cli.caseDir(), "ellipticMesh", polish, stop);
    return meshed.polishInterrupted ? interruptedExitCode : 0;
  });
}
