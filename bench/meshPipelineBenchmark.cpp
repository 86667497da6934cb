// Wall time of the in-process meshing pipeline, boundary to checked mesh: passage
// boundary, blade nodes, algebraic O-block, elliptic smoothing, lines redistributed,
// H-blocks, validity, then the quality Q (computeMeshQuality), as one episode of the
// policy's training or one evaluation of iterOptimize runs it.
//
//   taskset -c 1 build/bench/meshPipelineBenchmark [repetitions=5]
//       each tutorial at its passageDict.xml condition, default meshing parameters (the
//       blade is fitted first, not timed); median of the repetitions
//   taskset -c 1 build/bench/meshPipelineBenchmark sampler [passages=200] [seed=20261203]
//       blades and conditions from PassageSampler's ranges, meshing parameters at the
//       defaults; median and 95th percentile over the passages whose periodic boundaries
//       clear the blade (one run each)
//   build/bench/meshPipelineBenchmark digest [passages=50] [seed=20261203]
//       one line: a hash of every node coordinate's bits and of Q of the tutorials' meshes
//       and of the sampler passages' (defaults), then how many were valid. A change meant
//       to leave the meshes bit for bit as they were (a faster solver, a split of code)
//       must leave the line as it was. With a fourth argument `list`, each mesh's Q too
//       (%.9f, -1 invalid), one a line, to compare two builds mesh by mesh.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "TutorialPassage.hpp"
#include "passageMesh/core/HeapRetention.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/passage/PassageSampler.hpp"
#include "passageMesh/quality/MeshQuality.hpp"

using namespace passageMesh;

namespace {

struct CheckedMesh {
  HohMesh hoh;
  MeshQuality quality;
  double seconds = 0;
};

CheckedMesh checkedMesh(const BladeShape& blade, const PassageCondition& condition,
                        const MeshingParameters& parameters, MeshQualityWorkspace& workspace) {
  CheckedMesh result;
  const auto start = std::chrono::steady_clock::now();
  result.hoh = buildHohMesh(blade, condition, parameters);
  if (result.hoh.valid) result.quality = computeMeshQuality(result.hoh.mesh, workspace);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

double percentile(std::vector<double> values, double p) {
  std::sort(values.begin(), values.end());
  const std::size_t k = std::min(values.size() - 1, static_cast<std::size_t>(p * (values.size() - 1) + 0.5));
  return values[k];
}

int tutorials(int repetitions) {
  MeshQualityWorkspace workspace;
  std::printf("| blade | O-block | V-cycles | control sweeps | residual | median time [s] | Q_J min | Q_J mean | "
              "Q_S min | Q_S mean | Q |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& name : bench::tutorialNames()) {
    const bench::TutorialPassage tutorial = bench::loadTutorialPassage(name);
    const BladeShape blade(tutorial.blade);
    const auto parameters = MeshingParameters::defaults(tutorial.blade.chord);
    std::vector<double> seconds;
    CheckedMesh m;
    for (int r = 0; r < repetitions; ++r) {
      m = checkedMesh(blade, tutorial.condition, parameters, workspace);
      seconds.push_back(m.seconds);
    }
    const MeshQuality& q = m.quality;
    std::printf("| %s | %d x %d | %d | %d | %.2e | %.4f | %.3f | %.3f | %.3f | %.3f | %.6f%s |\n",
                name.c_str(), parameters.nT, m.hoh.nN, m.hoh.smoothing.iterations,
                m.hoh.smoothing.controlSweeps, m.hoh.smoothing.residual, percentile(seconds, 0.5),
                q.QJmin, q.QJavg, q.QSmin, q.QSavg, q.Q, m.hoh.valid ? "" : " (INVALID)");
  }
  return 0;
}

int sampled(int passages, std::uint64_t seed) {
  MeshQualityWorkspace workspace;
  std::vector<double> all, valid;
  int withPassage = 0;
  for (const PassageDraw& d : samplePassages(passages, seed)) {
    const BladeShape blade(d.blade);
    const CheckedMesh m = checkedMesh(blade, d.condition, MeshingParameters::defaults(d.blade.chord), workspace);
    if (m.hoh.problem.find("periodic boundary cuts the blade") != std::string::npos) continue;
    ++withPassage;
    all.push_back(m.seconds);
    if (m.hoh.valid) valid.push_back(m.seconds);
  }
  if (all.empty()) {
    std::printf("no passage of the %d draws clears its blade\n", passages);
    return 1;
  }
  std::printf("%d of %d draws with a passage (seed %llu, defaults); %zu valid\n", withPassage,
              passages, static_cast<unsigned long long>(seed), valid.size());
  std::printf("time per checked mesh [s], all with a passage: median %.4f, 95th percentile %.4f, max %.4f\n",
              percentile(all, 0.5), percentile(all, 0.95), percentile(all, 1.0));
  if (!valid.empty())
    std::printf("time per checked mesh [s], valid ones:          median %.4f, 95th percentile %.4f, max %.4f\n",
                percentile(valid, 0.5), percentile(valid, 0.95), percentile(valid, 1.0));
  return 0;
}

// FNV-1a over the bytes of each value.
struct Digest {
  std::uint64_t hash = 1469598103934665603ULL;
  void add(double v) {
    unsigned char bytes[sizeof v];
    std::memcpy(bytes, &v, sizeof v);
    for (unsigned char b : bytes) hash = (hash ^ b) * 1099511628211ULL;
  }
  void add(const CheckedMesh& m) {
    add(m.hoh.valid ? 1.0 : 0.0);
    for (const StructuredBlock& b : m.hoh.mesh.blocks) {
      for (double v : b.x) add(v);
      for (double v : b.y) add(v);
    }
    add(m.quality.Q);
  }
};

int digest(int passages, std::uint64_t seed, bool list) {
  MeshQualityWorkspace workspace;
  Digest d;
  int meshes = 0, valid = 0;
  auto add = [&](const BladeShape& blade, const PassageCondition& condition, double chord) {
    const CheckedMesh m = checkedMesh(blade, condition, MeshingParameters::defaults(chord), workspace);
    d.add(m);
    if (list) std::printf("mesh %d Q %.9f\n", meshes, m.quality.Q);
    ++meshes;
    valid += m.hoh.valid ? 1 : 0;
  };
  for (const std::string& name : bench::tutorialNames()) {
    const bench::TutorialPassage tutorial = bench::loadTutorialPassage(name);
    add(BladeShape(tutorial.blade), tutorial.condition, tutorial.blade.chord);
  }
  for (const PassageDraw& p : samplePassages(passages, seed)) add(BladeShape(p.blade), p.condition, p.blade.chord);
  std::printf("digest %016llx of %d meshes (%d valid)\n", static_cast<unsigned long long>(d.hash), meshes, valid);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  retainFreedHeapMemory();  // as every utility does (runUtility): the tools' timing
  if (argc > 1 && std::strcmp(argv[1], "digest") == 0)
    return digest(argc > 2 ? std::max(0, std::atoi(argv[2])) : 50,
                  argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 20261203,
                  argc > 4 && std::strcmp(argv[4], "list") == 0);
  if (argc > 1 && std::strcmp(argv[1], "sampler") == 0)
    return sampled(argc > 2 ? std::max(1, std::atoi(argv[2])) : 200,
                   argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 20261203);
  return tutorials(argc > 1 ? std::max(1, std::atoi(argv[1])) : 5);
}
