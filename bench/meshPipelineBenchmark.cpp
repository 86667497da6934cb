// Wall time of the in-process meshing pipeline (passage boundary, blade nodes, algebraic
// O-block, elliptic smoothing, H-blocks) for each tutorial at the paper's test condition
// (its passageDict.xml) with the default meshing parameters, and the quality Q of the
// result. The blade is fitted first (not timed).
//
//   taskset -c 1 build/bench/meshPipelineBenchmark [repetitions=5]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "TutorialPassage.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/quality/MeshQuality.hpp"

using namespace passageMesh;

int main(int argc, char** argv) {
  const int repetitions = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  std::printf("| blade | O-block | V-cycles | control sweeps | residual | median time [s] | Q_J min | Q_J mean | "
              "Q_S min | Q_S mean | Q |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& name : bench::tutorialNames()) {
    const bench::TutorialPassage tutorial = bench::loadTutorialPassage(name);
    const BladeShape blade(tutorial.blade);
    const auto& condition = tutorial.condition;
    const auto parameters = MeshingParameters::defaults(tutorial.blade.chord);
    std::vector<double> seconds;
    HohMesh hoh;
    for (int r = 0; r < repetitions; ++r) {
      const auto start = std::chrono::steady_clock::now();
      hoh = buildHohMesh(blade, condition, parameters);
      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(seconds.begin(), seconds.end());
    const MeshQuality q = computeMeshQuality(hoh.mesh);
    std::printf("| %s | %d x %d | %d | %d | %.2e | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f%s |\n",
                name.c_str(), parameters.nT, hoh.nN, hoh.smoothing.iterations, hoh.smoothing.controlSweeps, hoh.smoothing.residual,
                seconds[seconds.size() / 2], q.QJmin, q.QJavg, q.QSmin, q.QSavg, q.Q,
                hoh.valid ? "" : " (INVALID)");
  }
}
