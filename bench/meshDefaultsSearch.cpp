// The default meshing parameters chosen by measurement (issue 11 item 4): the one
// parameter set, lengths in chords, with the best median Q over random passages from
// PassageSampler (blades and conditions random, meshing parameters fixed), found by the
// optimiser library's default method started from etc/meshDictDefaults.xml, then
// confirmed on passages of another seed beside the current defaults.
//
//   build/bench/meshDefaultsSearch [budget=60] [passages=200] [threads=2]
//                                  [seed=20261201] [confirmSeed=20261202] [patternShare=0.15]
//                                  [keepTutorialsValid=1]
//
// An invalid mesh (or a periodic boundary through the blade) counts as Q = -1, so the
// median also rewards parameter sets that mesh more passages. With keepTutorialsValid a
// set that leaves any of the four tutorials (at their passageDict) without a valid mesh
// scores -1 as a whole: the defaults are what the tutorials mesh with. Prints the
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

// Q of each passage (a PassageDraw or a bench::TutorialPassage: anything with a blade and a
// condition) meshed with the set; invalidMeshQuality where the mesh is invalid.
template <class Passage>
std::vector<double> qualities(const std::vector<Passage>& passages, const Eigen::VectorXd& v,
                              int threads) {
  std::vector<double> q(passages.size());
  parallelFor(static_cast<int>(passages.size()), threads, [&](int k) {
    const Passage& d = passages[static_cast<std::size_t>(k)];
    const HohMesh hoh = buildHohMesh(BladeShape(d.blade), d.condition, forChord(v, d.blade.chord));
    q[static_cast<std::size_t>(k)] = hoh.valid ? computeMeshQuality(hoh.mesh).Q : invalidMeshQuality;
  });
  return q;
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
  const bool keepTutorialsValid = argc > 7 ? std::atoi(argv[7]) != 0 : true;
  if (budget < 1 || count < 1 || threads < 1) {
    std::fprintf(stderr, "usage: meshDefaultsSearch [budget>=1] [passages>=1] [threads>=1] [seed] [confirmSeed] [patternShare] [keepTutorialsValid]\n");
    return 2;
  }
  std::vector<bench::TutorialPassage> tutorials;
  for (const auto& name : bench::tutorialNames()) tutorials.push_back(bench::loadTutorialPassage(name));
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
      const auto tq = keepTutorialsValid ? qualities(tutorials, v, threads) : std::vector<double>{};
      const bool tutorialInvalid = std::any_of(tq.begin(), tq.end(), [](double q) { return q <= invalidMeshQuality; });
      values.push_back(tutorialInvalid ? invalidMeshQuality : quantile(qualities(passages, v, threads), 0.5));
    }
    return values;
  };
  const OptimizationResult result = optimize(meshingParameterProblem(1.0), objective, options);
  printParameters("current defaults", defaults);
  printParameters("best", result.best);
  std::printf("best median Q over the search passages (seed %llu): %.6f\n",
              static_cast<unsigned long long>(seed), result.bestValue);
  const auto before = qualities(tutorials, defaults, threads), after = qualities(tutorials, result.best, threads);
  std::printf("\ntutorials (Q, -1 invalid): | blade | current defaults | best of the search |\n");
  for (std::size_t k = 0; k < tutorials.size(); ++k)
    std::printf("| %s | %.4f | %.4f |\n", tutorials[k].name.c_str(), before[k], after[k]);

  const std::vector<PassageDraw> confirm = samplePassages(count, confirmSeed);
  std::printf("\nconfirmation on %d passages of seed %llu:\n| parameters | valid | Q 25 %% | Q median | Q 75 %% |\n|---|---|---|---|---|\n",
              count, static_cast<unsigned long long>(confirmSeed));
  report("current defaults", qualities(confirm, defaults, threads));
  report("best of the search", qualities(confirm, result.best, threads));
}
