// The O-block polish (libs/polish) on random passages: blades and conditions from
// PassageSampler's ranges, meshing parameters at the defaults; for each valid mesh, Q
// before and after, the step kept and the time (docs/benchmarks.md "The optional polish").
//   build/bench/polishSampler [passages=12] [seed=20261203] [first=0] [stride=1]
// Draws first, first + stride, ... of the `passages` draws (to share them between
// processes); one CSV line per valid mesh on stdout: draw,nT,nN,Qbefore,Qafter,step,seconds.
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/passage/PassageSampler.hpp"
#include "passageMesh/polish/OBlockPolish.hpp"

using namespace passageMesh;

int main(int argc, char** argv) {
  const int passages = argc > 1 ? std::atoi(argv[1]) : 12;
  const auto seed = static_cast<std::uint64_t>(argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 20261203ULL);
  const int first = argc > 3 ? std::atoi(argv[3]) : 0, stride = argc > 4 ? std::atoi(argv[4]) : 1;
  const auto draws = samplePassages(passages, seed);
  std::printf("draw,nT,nN,Qbefore,Qafter,step,seconds\n");
  for (int k = first; k < passages; k += stride) {
    const PassageDraw& d = draws[static_cast<std::size_t>(k)];
    const BladeShape blade(d.blade);
    HohMesh hoh = buildHohMesh(blade, d.condition, MeshingParameters::defaults(d.blade.chord));
    if (!hoh.valid) continue;
    const OBlockPolishReport r = polishOBlock(hoh.mesh);
    std::printf("%d,%d,%d,%.6f,%.6f,%d,%.1f\n", k, hoh.parameters.nT, hoh.nN, r.qualityBefore, r.qualityAfter,
                r.bestStep, r.seconds);
    std::fflush(stdout);
  }
  return 0;
}
