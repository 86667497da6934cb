// The O-block polish (libs/polish) on random passages: blades and conditions from
// PassageSampler's ranges, meshing parameters at the defaults; for each valid mesh, Q
// before and after, the step kept and the time (docs/benchmarks.md "The optional polish").
//   build/bench/polishSampler [passages=12] [seed=20261203] [first=0] [stride=1]
//   build/bench/polishSampler tutorials [best]
// The second form polishes the four tutorials at the defaults, or with `best` at
// iterOptimize's best parameters (docs/iterOptimize/<blade>-best-meshDict.xml); its lines
// start with the blade's name instead of the draw.
// Draws first, first + stride, ... of the `passages` draws (to share them between
// processes); one CSV line per valid mesh on stdout: draw,nT,nN,Qbefore,Qafter,step,seconds,
// then the Q of every step separated by spaces.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "TutorialPassage.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/passage/PassageSampler.hpp"
#include "passageMesh/polish/OBlockPolish.hpp"

using namespace passageMesh;

namespace {

// One CSV line: the mesh's label, its size, Q before and after, the step kept, the time,
// then every step's Q.
void polishAndPrint(const std::string& label, HohMesh& hoh) {
  const OBlockPolishReport r = polishOBlock(hoh.mesh);
  std::printf("%s,%d,%d,%.6f,%.6f,%d,%.1f,", label.c_str(), hoh.parameters.nT, hoh.nN, r.qualityBefore,
              r.qualityAfter, r.bestStep, r.seconds);
  for (const double q : r.stepQuality) std::printf(" %.6f", q);
  std::printf("\n");
  std::fflush(stdout);
}

void polishTutorials(bool best) {
  std::printf("blade,nT,nN,Qbefore,Qafter,step,seconds,stepQ\n");
  for (const auto& name : bench::tutorialNames()) {
    const bench::TutorialPassage t = bench::loadTutorialPassage(name);
    const auto dict = std::filesystem::path(PASSAGEMESH_SOURCE_DIR) / "docs" / "iterOptimize" / (name + "-best-meshDict.xml");
    const MeshingParameters p = best ? readMeshDict(dict, t.blade.chord) : MeshingParameters::defaults(t.blade.chord);
    HohMesh hoh = buildHohMesh(BladeShape(t.blade), t.condition, p);
    if (hoh.valid) polishAndPrint(name, hoh);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "tutorials") {
    polishTutorials(argc > 2 && std::string(argv[2]) == "best");
    return 0;
  }
  const int passages = argc > 1 ? std::atoi(argv[1]) : 12;
  const auto seed = static_cast<std::uint64_t>(argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 20261203ULL);
  const int first = argc > 3 ? std::atoi(argv[3]) : 0, stride = argc > 4 ? std::atoi(argv[4]) : 1;
  const auto draws = samplePassages(passages, seed);
  std::printf("draw,nT,nN,Qbefore,Qafter,step,seconds,stepQ\n");
  for (int k = first; k < passages; k += stride) {
    const PassageDraw& d = draws[static_cast<std::size_t>(k)];
    const BladeShape blade(d.blade);
    HohMesh hoh = buildHohMesh(blade, d.condition, MeshingParameters::defaults(d.blade.chord));
    if (!hoh.valid) continue;
    polishAndPrint(std::to_string(k), hoh);
  }
  return 0;
}
