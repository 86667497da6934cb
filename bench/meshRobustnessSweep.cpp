// Robustness sweep of the whole meshing pipeline (issue 3): random blades from the sampler,
// random conditions and meshing parameters over the method's whole ranges (method.md
// section 1), each meshed in-process. Every draw must end as a valid mesh or an explicit
// invalid-mesh result: no exception, no hang, no non-finite coordinate.
//
//   build/bench/meshRobustnessSweep [draws=500] [seed=20261122] [threads=1]
//
// Prints one line per draw (with the blade's clearance from the O-block's outer loop,
// bladeClearance, in chords), the valid fraction, and the draws with a passage counted by
// clearance (docs/benchmarks.md).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <string>
#include <vector>

#include "passageMesh/core/ParallelFor.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/passage/PassageBoundary.hpp"
#include "passageMesh/passage/PassageSampler.hpp"
#include "passageMesh/quality/MeshQuality.hpp"

using namespace passageMesh;

namespace {

struct Outcome {
  bool valid = false, finite = true, converged = false;
  bool moved = false;    // valid with moved parameters (HohMeshOptions::outerLoopRoom, clusteringMoves)
  int sweeps = 0;
  double seconds = 0;
  double clearance = 0;  // chords
  double quality = -1;   // Q of a valid mesh
  std::string problem;  // an invalid draw: why; a valid one: the later try that meshed it (or empty)
};

}  // namespace

int main(int argc, char** argv) {
  const int draws = argc > 1 ? std::atoi(argv[1]) : 500;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 20261122;
  const int threads = argc > 3 ? std::atoi(argv[3]) : 1;
  const std::vector<PassageDraw> all = samplePassages(draws, seed);
  std::vector<Outcome> outcomes(all.size());
  parallelFor(draws, threads, [&](int k) {
    const PassageDraw& d = all[static_cast<std::size_t>(k)];
    Outcome& out = outcomes[static_cast<std::size_t>(k)];
    const BladeShape blade(d.blade);
    out.clearance = bladeClearance(blade, PassageBoundary(blade, d.condition, d.parameters)) / d.blade.chord;
    const auto start = std::chrono::steady_clock::now();
    const HohMesh hoh = buildHohMesh(blade, d.condition, d.parameters);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.valid = hoh.valid;
    out.converged = hoh.smoothing.converged;
    out.sweeps = hoh.smoothing.iterations;
    out.finite = hasOnlyFiniteCoordinates(hoh.mesh);
    if (hoh.valid) out.quality = computeMeshQuality(hoh.mesh).Q;
    out.moved = !hoh.parametersMoved.empty();
    out.problem = hoh.valid ? (hoh.retryWithout.empty() ? "" : "meshed without orthogonality at " + hoh.retryWithout)
                            : hoh.problem;
    if (out.moved) out.problem += (out.problem.empty() ? "" : "; ") + ("moved: " + hoh.parametersMoved);
  });
  int valid = 0, notFinite = 0, notConverged = 0, moved = 0;
  double slowest = 0;
  for (int k = 0; k < draws; ++k) {
    const PassageDraw& d = all[static_cast<std::size_t>(k)];
    const Outcome& o = outcomes[static_cast<std::size_t>(k)];
    valid += o.valid;
    moved += o.valid && o.moved;
    notFinite += o.valid && !o.finite;
    notConverged += o.valid && !o.converged;
    slowest = std::max(slowest, o.seconds);
    std::printf("%4d pitch %.3f nO %5d nT %4d gammaLE %.2f gammaTE %.2f alpha %.2f clearance %6.3f: "
                "%s %d sweeps %.2f s Q %s %s\n", k, d.condition.pitch / d.blade.chord, d.condition.nO,
                d.parameters.nT, d.parameters.gammaLe, d.parameters.gammaTe,
                d.parameters.alphaCamber, o.clearance, o.valid ? "valid" : "INVALID", o.sweeps,
                o.seconds, o.valid ? std::to_string(o.quality).c_str() : "-", o.problem.c_str());
  }
  // The draws with a passage (no periodic boundary through the blade: issue 11's
  // denominator, which counts an interface through the blade as a passage), by clearance.
  // (Which draws have no passage is told by the problem's text: HohMesh.cpp,
  // outerLoopCrossing.) Clearance <= 0: an interface cuts the blade.
  const double edges[] = {-1e300, 0.0, 0.01, 0.02, 0.05, 0.1, 1e300};
  const int bins = static_cast<int>(std::size(edges)) - 1;
  std::printf("draws with a passage, by clearance (chords): valid / all\n");
  for (int b = 0; b < bins; ++b) {
    int inBin = 0, ok = 0;
    for (int k = 0; k < draws; ++k) {
      const Outcome& o = outcomes[static_cast<std::size_t>(k)];
      if (o.problem.find("periodic boundary cuts the blade") != std::string::npos) continue;
      if (o.clearance <= edges[b] || o.clearance > edges[b + 1]) continue;
      ++inBin;
      ok += o.valid;
    }
    if (b == 0) std::printf("  <= 0 (an interface cuts the blade): %d / %d\n", ok, inBin);
    else if (b + 1 < bins) std::printf("  (%.2f, %.2f]: %d / %d\n", edges[b], edges[b + 1], ok, inBin);
    else std::printf("  > %.2f: %d / %d\n", edges[b], ok, inBin);
  }
  std::printf("valid %d of %d (%.1f %%; %d of them with moved parameters); valid but not converged %d; "
              "non-finite %d; slowest %.2f s\n", valid, draws, 100.0 * valid / draws, moved, notConverged,
              notFinite, slowest);
  return notFinite == 0 ? 0 : 1;
}
