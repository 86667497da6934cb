// The robustness sweep (issue 3): 500 random passages over the method's whole ranges
// (blade, condition and meshing parameters; PassageSampler.hpp), seed fixed. Every draw
// must end as a valid mesh or an explicit invalid-mesh result: no exception, no hang (the
// smoother's cycles are capped; ctest's timeout catches the rest), no NaN or infinity in a
// valid mesh. bench/meshRobustnessSweep prints the same draws one by one.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>

#include "passageMesh/blade/BladeShape.hpp"
#include "passageMesh/core/ParallelFor.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/passage/PassageSampler.hpp"
#include "passageMesh/structured/CgnsWriter.hpp"  // validateStructuredMesh

namespace passageMesh {
namespace {

TEST(MeshRobustness, EveryRandomPassageEndsAsAValidMeshOrWithItsReason) {
  constexpr int draws = 500;
  const auto passages = samplePassages(draws, 20261122);
  std::atomic<int> valid{0};
  std::mutex failures;
  std::vector<std::string> wrong;
  parallelFor(draws, 0, [&](int k) {
    const PassageDraw& d = passages[static_cast<std::size_t>(k)];
    std::string what;
    try {
      const HohMesh hoh = buildHohMesh(BladeShape(d.blade), d.condition, d.parameters);
      if (hoh.valid) {
        ++valid;
        const std::string folded = findInvalidCell(hoh.mesh);
        if (!hoh.problem.empty()) what = "valid but with a problem: " + hoh.problem;
        else if (!hasOnlyFiniteCoordinates(hoh.mesh)) what = "valid with a non-finite coordinate";
        else if (!folded.empty()) what = "valid with " + folded;
        else {
          // Connected nodes coincide (periodic images a pitch apart): what writeCgns demands.
          try {
            validateStructuredMesh(hoh.mesh);
          } catch (const std::exception& e) {
            what = std::string("valid but not point-matched: ") + e.what();
          }
        }
      } else if (hoh.problem.empty()) {
        what = "invalid without a reason";
      }
    } catch (const std::exception& e) {
      what = std::string("threw: ") + e.what();
    }
    if (!what.empty()) {
      std::lock_guard<std::mutex> lock(failures);
      wrong.push_back("draw " + std::to_string(k) + ": " + what);
    }
  });
  for (const auto& w : wrong) ADD_FAILURE() << w;
  // 51 of these 500 were valid when this test was written, 72 since the second try
  // without outer orthogonality, 84 since the wall blend in log distance, 88 since the
  // control grid resampled in the loop index, 94 since the tries without the wall's
  // orthogonality, 130 since the outer loop is moved away where it leaves the blade too
  // little room and the node clustering toward the defaults' (docs/benchmarks.md); fewer
  // means the mesher got less robust. Raise the floor when it gets better.
  EXPECT_GE(valid.load(), 127) << "valid meshes among " << draws << " random passages";
  std::printf("valid %d of %d random passages\n", valid.load(), draws);
}

}  // namespace
}  // namespace passageMesh
