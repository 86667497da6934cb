// Robustness sweep of the whole meshing pipeline (issue 3): random blades from the sampler,
// random conditions and meshing parameters over the method's whole ranges (method.md
// section 1), each meshed in-process. Every draw must end as a valid mesh or an explicit
// invalid-mesh result: no exception, no hang, no non-finite coordinate.
//
//   build/bench/meshRobustnessSweep [draws=500] [seed=20261122] [threads=1]
//
// Prints one line per draw and the valid fraction (docs/benchmarks.md).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "passageMesh/blade/BladeSampler.hpp"
#include "passageMesh/core/ParallelFor.hpp"
#include "passageMesh/mesh/HohMesh.hpp"

using namespace passageMesh;

namespace {

struct Draw {
  BladeParameters blade;
  PassageCondition condition;
  MeshingParameters parameters;
};

struct Outcome {
  bool valid = false, finite = true, converged = false;
  int sweeps = 0;
  double seconds = 0;
  std::string problem;
};

double between(std::mt19937_64& rng, double a, double b) { return a + (b - a) * uniform01(rng); }

}  // namespace

int main(int argc, char** argv) {
  const int draws = argc > 1 ? std::atoi(argv[1]) : 500;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 20261122;
  const int threads = argc > 3 ? std::atoi(argv[3]) : 1;
  BladeSampler sampler(BladeParameterRange::readDefault(), seed);
  std::mt19937_64 rng(seed + 1);
  std::vector<Draw> all(static_cast<std::size_t>(draws));
  for (auto& d : all) {
    d.blade = sampler.next();
    const double c = d.blade.chord;
    d.condition.pitch = between(rng, 0.3, 1.0) * c;
    d.condition.xIn = between(rng, 0.0, 1.0) * c;
    d.condition.xOut = between(rng, 0.0, 1.0) * c;
    d.condition.nO = static_cast<int>(std::lround(between(rng, 10000, 50000)));
    d.condition.firstCellHeight = between(rng, 2e-5, 2e-4) * c;
    std::array<double, MeshingParameters::size> x;
    const auto lo = MeshingParameters::lowerBounds(c), hi = MeshingParameters::upperBounds(c);
    for (std::size_t k = 0; k < x.size(); ++k) x[k] = between(rng, lo[k], hi[k]);
    d.parameters = MeshingParameters::fromArray(x);
  }
  std::vector<Outcome> outcomes(all.size());
  parallelFor(draws, threads, [&](int k) {
    const Draw& d = all[static_cast<std::size_t>(k)];
    Outcome& out = outcomes[static_cast<std::size_t>(k)];
    const auto start = std::chrono::steady_clock::now();
    const HohMesh hoh = buildHohMesh(BladeShape(d.blade), d.condition, d.parameters);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.valid = hoh.valid;
    out.problem = hoh.problem;
    out.converged = hoh.smoothing.converged;
    out.sweeps = hoh.smoothing.iterations;
    for (const auto& b : hoh.mesh.blocks)
      for (std::size_t n = 0; n < b.x.size(); ++n)
        if (!std::isfinite(b.x[n]) || !std::isfinite(b.y[n])) out.finite = false;
  });
  int valid = 0, notFinite = 0, notConverged = 0;
  double slowest = 0;
  for (int k = 0; k < draws; ++k) {
    const Draw& d = all[static_cast<std::size_t>(k)];
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
