// policyMesh: meshes a blade passage in one shot with a trained policy (issue 12,
// docs/policy.md): one forward pass of the actor (of each member of an ensemble, whose
// actions are averaged) maps the blade and the condition to the meshing parameters, then
// the HOH mesh is built, written and measured in the same run. Where an ensemble's mean
// action gives an invalid mesh, its members' own actions are tried in turn and the first
// valid mesh is kept (Policy::actionsInTurn). -polish: the O-block's
// polish as in ellipticMesh; Ctrl-C ends it early, the mesh is written with the polish so
// far and the exit code is 130.
//   reads  constant/bladeParameters.xml, system/passageDict.xml, the policy
//          (-policy FILE.xml; default etc/policy/policy.xml, the shipped one)
//   writes system/meshDict.xml (the policy's parameters), mesh/passage.cgns,
//          mesh/passage.vtm + mesh/passage/<block>.vts
// A condition or blade outside the policy's training ranges gets a warning naming the
// value. An invalid mesh is an error (exit 1; the parameters are printed, nothing is
// written: meshDict.xml is written with the mesh files, all or none).
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/core/InterruptFlag.hpp"
#include "passageMesh/core/NumberFormat.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/passage/PassageCase.hpp"
#include "passageMesh/policy/Policy.hpp"
#include "passageMesh/quality/MeshQuality.hpp"
#include "passageMesh/workflow/PassageMeshFiles.hpp"

using namespace passageMesh;
namespace po = boost::program_options;

int main(int argc, char* argv[]) {
  return runUtility("policyMesh", [&] {
    CommandLine cli("policyMesh",
                    "Meshes the case's blade passage in one shot: a trained policy gives the\n"
                    "meshing parameters (written to system/meshDict.xml), then the HOH mesh is\n"
                    "built, written (mesh/passage.cgns, mesh/passage.vtm) and its quality Q printed.");
    cli.addOptions()("policy", po::value<std::string>(),
                     "the policy's .xml file (default: etc/policy/policy.xml, the shipped policy)")(
        "polish", polishOptionHelp);
    if (!cli.parse(argc, argv)) return 0;
    const std::filesystem::path policyFile =
        cli.values().count("policy") ? std::filesystem::path(cli.values()["policy"].as<std::string>())
                                     : defaultPolicyFile();
    const Policy policy = Policy::load(policyFile);
    PassageCase input = readPassageCase(cli.caseDir(), "policyMesh");
    const BladeParameters& blade = input.blade.parameters();

    const auto start = std::chrono::steady_clock::now();
    const PolicyState state = policy.state(blade, input.condition);
    for (const auto& w : stateOutsideTraining(state)) std::cerr << "policyMesh: warning: " << w << "\n";
    const std::vector<PolicyAction> actions = policy.actionsInTurn(state);
    input.parameters = meshingParametersOf(actions.front(), blade.chord);
    const double forwardSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // An ensemble whose mean action folds the mesh falls back on its members' own actions,
    // in turn (Policy::actionsInTurn); the mesh kept is the one written.
    HohMesh built = buildHohMesh(input.blade, input.condition, input.parameters);
    for (std::size_t i = 1; i < actions.size() && !built.valid; ++i) {
      std::printf("policyMesh: the mesh of the members' mean action is invalid; member %zu's own action instead\n",
                  i);
      input.parameters = meshingParametersOf(actions[i], blade.chord);
      built = buildHohMesh(input.blade, input.condition, input.parameters);
    }

    // trainedEpisodes counts the run that wrote a policy file only (a run started with
    // -actorFrom does not add its start's), so an ensemble is described by its validation.
    const PolicyProvenance& provenance = policy.provenance();
    std::string about = policy.memberCount() > 1
                            ? "an ensemble of " + std::to_string(policy.memberCount()) + " members"
                            : std::to_string(provenance.episodes) + " episodes in the run that wrote it";
    if (provenance.validationMeanReward != 0)
      about += ", validation mean reward " + formatRounded(provenance.validationMeanReward);
    std::printf("policyMesh: policy %s (%s), forward pass %.3f ms (the first: LibTorch starting up); meshing parameters "
                "(yIn, yOut in metres; written to system/meshDict.xml with the mesh):\n",
                policyFile.c_str(), about.c_str(), 1e3 * forwardSeconds);
    const auto values = input.parameters.toArray();
    for (int k = 0; k < MeshingParameters::size; ++k)
      std::printf("    %-12s %.17g\n", MeshingParameters::names()[k].c_str(), values[k]);

    const bool polish = cli.values().count("polish") > 0;
    const std::atomic<bool>* stop = polish ? &installInterruptFlag() : nullptr;
    const MeshedCase meshed =
        meshCaseAndWrite(input, std::move(built), cli.caseDir(), "policyMesh", polish, stop,
                         {fileWithContent(cli.caseDir() / "system" / "meshDict.xml", meshDictXml(input.parameters))});
    const HohMesh& hoh = meshed.hoh;
    const MeshQuality q = computeMeshQuality(hoh.mesh);
    std::printf("policyMesh: Q = %.17g (min Q_J %.6f, mean Q_J %.6f, min Q_S %.6f, mean Q_S %.6f)\n", q.Q,
                q.QJmin, q.QJavg, q.QSmin, q.QSavg);
    return meshed.polishInterrupted ? interruptedExitCode : 0;
  });
}
