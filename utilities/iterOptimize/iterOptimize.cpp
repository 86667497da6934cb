// iterOptimize: the best meshing parameters for one blade passage by iteration (issue 5):
// an optimiser maximises the mesh quality Q over the meshing parameters (method.md
// sections 1, 4, 5), starting from the case's own (docs/optimization.md).
//   reads  constant/bladeParameters.xml, system/passageDict.xml,
//          system/meshDict.xml (optional: the start; missing keys take the defaults)
//   writes system/meshDict.xml (the best; the first run keeps the old one as
//          meshDict.xml.orig), postProcessing/iterOptimize/history.csv, convergence.png
// Exit codes: 0 done, 1 bad input, 2 no valid mesh found (meshDict.xml kept),
// 130 interrupted by Ctrl-C (the files hold the best so far; a second Ctrl-C aborts).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <string>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/InterruptFlag.hpp"
#include "passageMesh/core/JoinedWords.hpp"
#include "passageMesh/passage/PassageCase.hpp"
#include "passageMesh/policy/DrlOptimizer.hpp"
#include "passageMesh/workflow/MeshingOptimization.hpp"
#include "passageMesh/workflow/MeshingOptimizationFiles.hpp"
#include "passageMesh/workflow/OptimizationProgressLine.hpp"

using namespace passageMesh;
namespace po = boost::program_options;

namespace {

std::string methodList() { return joinedWords(optimizerMethods(), ", "); }

// The optimiser's options from the command line; bad values are input errors, found
// before the case is read or anything is written.
OptimizerOptions optimizerOptions(const po::variables_map& values) {
  OptimizerOptions options;
  options.method = values["method"].as<std::string>();
  options.budget = values["budget"].as<long>();
  const long seed = values["seed"].as<long>();
  options.threads = values["threads"].as<int>();
  const auto& methods = optimizerMethods();
  if (std::find(methods.begin(), methods.end(), options.method) == methods.end())
    throw InputError("command line: -method: unknown method '" + options.method + "' (known: " +
                     methodList() + ")");
  if (options.budget < 1) throw InputError("command line: -budget: at least 1 evaluation");
  if (seed < 0) throw InputError("command line: -seed: expected a non-negative integer");
  if (options.threads < 0) throw InputError("command line: -threads: expected 0 (all cores) or more");
  options.seed = static_cast<std::uint64_t>(seed);
  return options;
}

void printBest(const MeshingOptimization& run) {
  const std::string patternSearch =
      run.result.patternSearchEvaluations > 0
          ? ", " + std::to_string(run.result.patternSearchEvaluations) + " of them by the final pattern search"
          : "";
  std::printf("iterOptimize: %ld evaluations (%d %s of %s%s); start Q %.17g, best Q %.17g "
              "(evaluation %ld)\n  best meshing parameters (yIn, yOut in metres):\n",
              run.result.evaluations, run.result.restarts, run.result.restarts == 1 ? "start" : "starts",
              run.result.method.c_str(), patternSearch.c_str(),
              run.startQuality(), run.result.bestValue, run.bestEvaluation());
  const auto& names = MeshingParameters::names();
  const auto values = run.best.toArray();
  for (int k = 0; k < MeshingParameters::size; ++k)
    std::printf("    %-12s %.17g\n", names[k].c_str(), values[k]);
}

}  // namespace

int main(int argc, char* argv[]) {
  registerDrlOptimizer();
  return runUtility("iterOptimize", [&] {
    CommandLine cli("iterOptimize",
                    "Finds the meshing parameters of the best mesh quality Q for the case's\n"
                    "blade passage by iteration, starting from system/meshDict.xml (or the\n"
                    "defaults), and writes them to system/meshDict.xml. Ctrl-C stops at the next\n"
                    "batch and writes the best so far (exit code 130).");
    cli.addOptions()
        ("method", po::value<std::string>()->default_value("cmaes"),
         ("optimiser: " + methodList() + " (docs/optimization.md)").c_str())
        ("budget", po::value<long>()->default_value(1000), "meshes to build and measure")
        ("seed", po::value<long>()->default_value(1), "random seed (same seed, same run)")
        ("threads", po::value<int>()->default_value(0), "meshes built at once (0 = all cores)");
    if (!cli.parse(argc, argv)) return 0;
    OptimizerOptions options = optimizerOptions(cli.values());
    const PassageCase input = readPassageCase(cli.caseDir(), "iterOptimize");

    options.stop = &installInterruptFlag();
    OptimizationProgressLine progress("iterOptimize");
    options.progress = [&progress](const OptimizationProgress& p) { progress(p); };
    std::printf("iterOptimize: method %s, budget %ld meshes, seed %llu, threads %s\n",
                options.method.c_str(), options.budget, static_cast<unsigned long long>(options.seed),
                options.threads == 0 ? "all cores" : std::to_string(options.threads).c_str());
    std::fflush(stdout);
    const MeshingOptimization run = optimizeMeshingParameters(input, options);
    progress.finish();

    const MeshingOptimizationFiles files = writeMeshingOptimizationFiles(cli.caseDir(), run);
    for (const auto& w : files.warnings) std::cerr << "iterOptimize: warning: " << w << "\n";
    if (!run.result.history.empty()) printBest(run);
    for (const auto& f : files.written) std::printf("  wrote %s\n", f.string().c_str());
    if (run.result.stopped) {
      std::fprintf(stderr, "iterOptimize: interrupted after %ld of %ld evaluations; the files "
                   "hold the best so far\n", run.result.evaluations, options.budget);
      return interruptedExitCode;
    }
    return run.foundValidMesh() ? 0 : 2;
  });
}
