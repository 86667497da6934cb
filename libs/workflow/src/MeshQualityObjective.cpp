#include "passageMesh/workflow/MeshQualityObjective.hpp"

#include <memory>

#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/optimize/MeshingParameterSpace.hpp"
#include "passageMesh/quality/MeshQuality.hpp"

namespace passageMesh {

double meshQualityOf(const PassageCase& input, const MeshingParameters& parameters,
                     const HohMeshOptions& options) {
  const HohMesh hoh = buildHohMesh(input.blade, input.condition, parameters, options);
  if (!hoh.valid) return invalidMeshQuality;
  // One workspace per thread: after the first mesh of a size it allocates nothing more.
  thread_local MeshQualityWorkspace workspace;
  return computeMeshQuality(hoh.mesh, workspace).Q;
}

PointObjective meshQualityPointObjective(const PassageCase& input) {
  auto shared = std::make_shared<const PassageCase>(input);
  return [shared](const Eigen::VectorXd& point) {
    return meshQualityOf(*shared, toMeshingParameters(point));
  };
}

BatchObjective meshQualityObjective(const PassageCase& input, int threads) {
  return evaluateInParallel(meshQualityPointObjective(input), threads);
}

}  // namespace passageMesh
