// meshQualityBenchmark: the mesh-quality timing of docs/benchmarks.md.
//   build/bench/meshQualityBenchmark --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
// Q of the algebraic HOH mesh of the typical test blade at the paper's size (nO = 30000:
// an O-block of 301 x 100 nodes), one core, with a reused workspace (what an optimiser
// does) and without.
#include <benchmark/benchmark.h>

#include <string>

#include "../tests/blade/BladeTestData.hpp"
#include "../tests/passage/PassageTestData.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/quality/MeshQuality.hpp"

using namespace passageMesh;

namespace {

const HohMesh& paperSizedMesh() {
  static const HohMesh hoh = [] {
    const BladeShape blade(testData::typicalTurbineBlade());
    const double chord = blade.parameters().chord;
    MeshingParameters parameters = MeshingParameters::defaults(chord);
    parameters.gammaLe = parameters.gammaTe = 2;
    return buildHohMesh(blade, testData::paperCondition(chord), parameters);
  }();
  return hoh;
}

void reportMesh(benchmark::State& state, const MeshQuality& q) {
  const StructuredBlock& o = paperSizedMesh().mesh.blocks[1];
  state.SetLabel("O-block " + std::to_string(o.ni) + " x " + std::to_string(o.nj) + ", Q " +
                 std::to_string(q.Q) + (q.valid ? " (valid)" : " (INVALID)"));
}

void meshQualityWithWorkspace(benchmark::State& state) {
  const StructuredMesh& mesh = paperSizedMesh().mesh;
  MeshQualityWorkspace workspace;
  MeshQuality q;
  for (auto _ : state) {
    q = computeMeshQuality(mesh, workspace);
    benchmark::DoNotOptimize(q);  // the whole value: DoNotOptimize(q.Q) clobbered the double
  }
  reportMesh(state, q);
}

void meshQualityFresh(benchmark::State& state) {
  const StructuredMesh& mesh = paperSizedMesh().mesh;
  MeshQuality q;
  for (auto _ : state) {
    q = computeMeshQuality(mesh);
    benchmark::DoNotOptimize(q);  // the whole value: DoNotOptimize(q.Q) clobbered the double
  }
  reportMesh(state, q);
}

}  // namespace

BENCHMARK(meshQualityWithWorkspace)->Unit(benchmark::kMicrosecond);
BENCHMARK(meshQualityFresh)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
