// policyMeshBenchmark: policyMesh's work in memory, timed (docs/benchmarks.md "policyMesh"):
// the forward pass alone (median of 1000) and forward pass + mesh + Q (median of REPEATS).
//   policyMeshBenchmark POLICY.xml CASE_DIR [REPEATS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/passage/PassageCase.hpp"
#include "passageMesh/policy/Policy.hpp"
#include "passageMesh/quality/MeshQuality.hpp"

using namespace passageMesh;

namespace {

double seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char* argv[]) {
  // A missing or corrupt file ends in one line on stderr and exit code 1, not a crash.
  return runUtility("policyMeshBenchmark", [&] {
    if (argc < 3) {
      std::fprintf(stderr, "usage: policyMeshBenchmark POLICY.xml CASE_DIR [REPEATS]\n");
      return 2;
    }
    const Policy policy = Policy::load(argv[1]);
    const PassageCase input = readPassageCase(argv[2], "policyMeshBenchmark");
    const int repeats = argc > 3 ? std::stoi(argv[3]) : 5;
    const BladeParameters& blade = input.blade.parameters();

    std::vector<double> forward;
    for (int r = 0; r < 1000; ++r) {
      const auto start = std::chrono::steady_clock::now();
      const MeshingParameters p = meshingParametersOf(policy.act(policy.state(blade, input.condition)), blade.chord);
      forward.push_back(seconds(start));
      if (p.nT < 0) return 1;  // keeps the call from being optimised away
    }
    std::vector<double> whole;
    double q = 0;
    for (int r = 0; r < repeats; ++r) {
      const auto start = std::chrono::steady_clock::now();
      const MeshingParameters p = meshingParametersOf(policy.act(policy.state(blade, input.condition)), blade.chord);
      const HohMesh hoh = buildHohMesh(input.blade, input.condition, p);
      q = hoh.valid ? computeMeshQuality(hoh.mesh).Q : invalidMeshQuality;
      whole.push_back(seconds(start));
    }
    std::printf("%s on %s (nO %d): forward pass median %.3f ms; forward + mesh + Q median %.1f ms (%d runs); Q %.17g\n",
                argv[1], argv[2], input.condition.nO, 1e3 * median(forward), 1e3 * median(whole), repeats, q);
    return 0;
  });
}
