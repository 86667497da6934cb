// The default meshing parameters chosen by measurement (issue 11 item 4): the one
// parameter set, lengths in chords, with the best median Q over random passages from
// PassageSampler (blades and conditions random, meshing parameters fixed), found by the
// optimiser library's default method started from etc/meshDictDefaults.xml, then
// confirmed on passages of another seed beside the current defaults.
//
//   build/bench/meshDefaultsSearch [budget=60] [passages=200] [threads=2]
//                                  [seed=20261201] [confirmSeed=20261202] [patternShare=0.15]
//                                  [tutorialFloor=0]
//
// An invalid mesh (or a periodic boundary through the blade) counts as Q = -1, so the
// median also rewards parameter sets that mesh more passages. A set scores -1 as a whole
// when it leaves any of the four tutorials (at their passageDict) without a valid mesh
// (the defaults are what the tutorials mesh with), or any tutorial at pitch 0.3, 0.5, 0.75
// or 1 chord and nO 10000, 30000 or 50000 where its periodic boundaries clear the blade
// (issue 11's validity must-show; since 2026-12-04). tutorialFloor < 0: the tutorials are
// not meshed at all. A tutorial's Q below tutorialFloor costs the median ten times the
// shortfall (issue 11 asks for Q >= 0.60 on every tutorial at the defaults; a penalty,
// not a cliff, so that the optimiser sees which way the floor lies). Runs before
// 2026-12-04 passed keepTutorialsValid = 1 here, which is tutorialFloor 0. Prints the
// progress, the best set as meshDict lines, the tutorials' Q with both sets and the
// confirmation table (docs/benchmarks.md).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "TutorialPassage.hpp"
#include "passageMesh/core/ParallelFor.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/optimize/MeshingParameterSpace.hpp"
#include "passageMesh/optimize/Optimizer.hpp"
#include "passageMesh/passage/PassageSampler.hpp"
#include "passageMesh/quality/MeshQuality.hpp"

using namespace passageMesh;

namespace {

// Parameters in chords (the optimiser's vector for chord 1) made lengths for `chord`.
MeshingParameters forChord(const Eigen::VectorXd& v, double chord) {
  MeshingParameters p = toMeshingParameters(v);
  p.yIn *= chord;
  p.yOut *= chord;
  return p;
}

// Meshes each passage (a PassageDraw or a bench::TutorialPassage: anything with a blade
// and a condition) with the set, on `threads` threads, and keeps what `score` makes of
// each mesh.
template <class Passage, class Score>
std::vector<double> scoreMeshes(const std::vector<Passage>& passages, const Eigen::VectorXd& v,
                                int threads, Score score) {
  std::vector<double> values(passages.size());
  parallelFor(static_cast<int>(passages.size()), threads, [&](int k) {
    const Passage& d = passages[static_cast<std::size_t>(k)];
    values[static_cast<std::size_t>(k)] =
        score(buildHohMesh(BladeShape(d.blade), d.condition, forChord(v, d.blade.chord)));
  });
  return values;
}

// Q of each passage meshed with the set; invalidMeshQuality where the mesh is invalid.
template <class Passage>
std::vector<double> qualities(const std::vector<Passage>& passages, const Eigen::VectorXd& v,
                              int threads) {
  return scoreMeshes(passages, v, threads, [](const HohMesh& hoh) {
    return hoh.valid ? computeMeshQuality(hoh.mesh).Q : invalidMeshQuality;
  });
}

// The tutorials at every pitch of the method's range (0.3, 0.5, 0.75, 1 chord) and nO
// 10000, 30000, 50000: the defaults must mesh each of them wherever its periodic
// boundaries leave the blade a passage (the test TutorialMesh.DefaultParameters...).
std::vector<bench::TutorialPassage> pitchAndNodeCountVariants(const std::vector<bench::TutorialPassage>& tutorials) {
  std::vector<bench::TutorialPassage> variants;
  for (const auto& t : tutorials)
    for (double pitch : {0.3, 0.5, 0.75, 1.0})
      for (int nO : {10000, 30000, 50000}) {
        bench::TutorialPassage v = t;
        v.condition.pitch = pitch * t.blade.chord;
        v.condition.nO = nO;
        variants.push_back(v);
      }
  return variants;
}

// How many of the passages the set leaves without a mesh although their periodic
// boundaries clear the blade.
long unmeshedPassages(const std::vector<bench::TutorialPassage>& passages, const Eigen::VectorXd& v,
                      int threads) {
  const std::vector<double> failed = scoreMeshes(passages, v, threads, [](const HohMesh& hoh) {
    return !hoh.valid && hoh.problem.find("periodic boundary cuts the blade") == std::string::npos ? 1.0 : 0.0;
  });
  return std::count(failed.begin(), failed.end(), 1.0);
}

// Value at fraction f of the sorted values (0.5: the median).
double quantile(std::vector<double> v, double f) {
  std::sort(v.begin(), v.end());
  const double position = f * static_cast<double>(v.size() - 1);
  const auto below = static_cast<std::size_t>(position);
  const std::size_t above = std::min(below + 1, v.size() - 1);
  return v[below] + (position - static_cast<double>(below)) * (v[above] - v[below]);
}

void report(const char* label, const std::vector<double>& q) {
  const long valid = std::count_if(q.begin(), q.end(), [](double x) { return x > invalidMeshQuality; });
  std::printf("| %s | %ld of %zu | %.4f | %.4f | %.4f |\n", label, valid, q.size(), quantile(q, 0.25),
              quantile(q, 0.5), quantile(q, 0.75));
}

// The set in chords: yIn and yOut (the first two) with the suffix c, as meshDict takes them.
void printParameters(const char* label, const Eigen::VectorXd& v) {
  const auto& names = MeshingParameters::names();
  const auto values = toMeshingParameters(v).toArray();
  std::printf("%s:", label);
  for (int k = 0; k < MeshingParameters::size; ++k)
    std::printf(" %s %.6g%s", names[k].c_str(), values[static_cast<std::size_t>(k)], MeshingParameters::table()[k].length ? "c" : "");
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  const long budget = argc > 1 ? std::atol(argv[1]) : 60;
  const int count = argc > 2 ? std::atoi(argv[2]) : 200;
  const int threads = argc > 3 ? std::atoi(argv[3]) : 2;
  const std::uint64_t seed = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 20261201;
  const std::uint64_t confirmSeed = argc > 5 ? std::strtoull(argv[5], nullptr, 10) : 20261202;
  const double patternShare = argc > 6 ? std::atof(argv[6]) : 0.15;
  const double tutorialFloor = argc > 7 ? std::atof(argv[7]) : 0.0;
  const bool meshTutorials = tutorialFloor >= 0;
  if (budget < 1 || count < 1 || threads < 1) {
    std::fprintf(stderr, "usage: meshDefaultsSearch [budget>=1] [passages>=1] [threads>=1] [seed] [confirmSeed] [patternShare] [tutorialFloor]\n");
    return 2;
  }
  std::vector<bench::TutorialPassage> tutorials;
  for (const auto& name : bench::tutorialNames()) tutorials.push_back(bench::loadTutorialPassage(name));
  const std::vector<bench::TutorialPassage> variants = pitchAndNodeCountVariants(tutorials);
  const std::vector<PassageDraw> passages = samplePassages(count, seed);
  const Eigen::VectorXd defaults = toOptimizerVector(MeshingParameters::defaults(1.0));
  const auto start = std::chrono::steady_clock::now();
  OptimizerOptions options;
  options.budget = budget;
  options.seed = 1;
  options.start = defaults;
  options.patternSearchShare = patternShare;
  options.progress = [&](const OptimizationProgress& p) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("evaluations %ld of %ld, best median Q %.6f, %.0f s\n", p.evaluations, p.budget,
                p.bestValue, s);
    std::fflush(stdout);
  };
  const BatchObjective objective = [&](const std::vector<Eigen::VectorXd>& points) {
    std::vector<double> values;
    for (const auto& v : points) {
      const auto tq = meshTutorials ? qualities(tutorials, v, threads) : std::vector<double>{};
      const bool tutorialInvalid = std::any_of(tq.begin(), tq.end(), [](double q) { return q <= invalidMeshQuality; });
      const bool rejected = tutorialInvalid || (meshTutorials && unmeshedPassages(variants, v, threads) > 0);
      double shortfall = 0;
      for (double q : tq) shortfall += std::max(0.0, tutorialFloor - q);
      values.push_back(rejected ? invalidMeshQuality
                                : quantile(qualities(passages, v, threads), 0.5) - 10 * shortfall);
    }
    return values;
  };
  const OptimizationResult result = optimize(meshingParameterProblem(1.0), objective, options);
  printParameters("current defaults", defaults);
  printParameters("best", result.best);
  std::printf("best median Q over the search passages (seed %llu): %.6f\n",
              static_cast<unsigned long long>(seed), result.bestValue);
  const auto before = qualities(tutorials, defaults, threads), after = qualities(tutorials, result.best, threads);
  std::printf("\ntutorials at pitch 0.3-1 chord and nO 10000-50000 without a mesh (periodic boundaries clear): "
              "current defaults %ld, best of the search %ld of %zu\n",
              unmeshedPassages(variants, defaults, threads), unmeshedPassages(variants, result.best, threads),
              variants.size());
  std::printf("\ntutorials (Q, -1 invalid): | blade | current defaults | best of the search |\n");
  for (std::size_t k = 0; k < tutorials.size(); ++k)
    std::printf("| %s | %.4f | %.4f |\n", tutorials[k].name.c_str(), before[k], after[k]);

  const std::vector<PassageDraw> confirm = samplePassages(count, confirmSeed);
  std::printf("\nconfirmation on %d passages of seed %llu:\n| parameters | valid | Q 25 %% | Q median | Q 75 %% |\n|---|---|---|---|---|\n",
              count, static_cast<unsigned long long>(confirmSeed));
  report("current defaults", qualities(confirm, defaults, threads));
  report("best of the search", qualities(confirm, result.best, threads));
}
