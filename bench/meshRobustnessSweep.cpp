// Robustness sweep of the whole meshing pipeline (issue 3): random blades from the sampler,
// random conditions and meshing parameters over the method's whole ranges (method.md
// section 1), each meshed in-process. Every draw must end as a valid mesh or an explicit
// invalid-mesh result: no exception, no hang, no non-finite coordinate.
//
//   build/bench/meshRobustnessSweep [draws=500] [seed=20261122] [threads=1]
//
// Prints one line per draw and the valid fraction (docs/benchmarks.md).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "passageMesh/core/ParallelFor.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/passage/PassageSampler.hpp"

using namespace passageMesh;

namespace {

struct Outcome {
  bool valid = false, finite = true, converged = false;
  int sweeps = 0;
  double seconds = 0;
  std::string problem;
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
    const auto start = std::chrono::steady_clock::now();
    const HohMesh hoh = buildHohMesh(BladeShape(d.blade), d.condition, d.parameters);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.valid = hoh.valid;
    out.problem = hoh.problem;
    out.converged = hoh.smoothing.converged;
    out.sweeps = hoh.smoothing.iterations;
    out.finite = hasOnlyFiniteCoordinates(hoh.mesh);
  });
  int valid = 0, notFinite = 0, notConverged = 0;
  double slowest = 0;
  for (int k = 0; k < draws; ++k) {
    const PassageDraw& d = all[static_cast<std::size_t>(k)];
    const Outcome& o = outcomes[static_cast<std::size_t>(k)];
    valid += o.valid;
    notFinite += o.valid && !o.finite;
    notConverged += o.valid && !o.converged;
    slowest = std::max(slowest, o.seconds);
    std::printf("%4d pitch %.3f nO %5d nT %4d gammaLE %.2f gammaTE %.2f alpha %.2f: %s %d sweeps "
                "%.2f s %s\n", k, d.condition.pitch / d.blade.chord, d.condition.nO,
                d.parameters.nT, d.parameters.gammaLe, d.parameters.gammaTe,
                d.parameters.alphaCamber, o.valid ? "valid" : "INVALID", o.sweeps, o.seconds,
                o.problem.c_str());
  }
  std::printf("valid %d of %d (%.1f %%); valid but not converged %d; non-finite %d; slowest "
              "%.2f s\n", valid, draws, 100.0 * valid / draws, notConverged, notFinite, slowest);
  return notFinite == 0 ? 0 : 1;
}
