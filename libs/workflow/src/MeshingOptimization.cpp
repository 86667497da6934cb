#include "passageMesh/workflow/MeshingOptimization.hpp"

#include <limits>

#include "passageMesh/optimize/MeshingParameterSpace.hpp"
#include "passageMesh/quality/MeshQuality.hpp"
#include "passageMesh/workflow/MeshQualityObjective.hpp"

namespace passageMesh {

double MeshingOptimization::startQuality() const {
  return result.history.empty() ? std::numeric_limits<double>::quiet_NaN()
                                : result.history.front().value;
}

bool MeshingOptimization::foundValidMesh() const {
  return !result.history.empty() && result.bestValue > invalidMeshQuality;
}

long MeshingOptimization::bestEvaluation() const {
  for (const Evaluation& e : result.history)
    if (e.value == result.bestValue) return e.index;
  return -1;
}

MeshingOptimization optimizeMeshingParameters(const PassageCase& input, OptimizerOptions options) {
  MeshingOptimization run;
  run.box = meshingParameterProblem(input.blade.parameters().chord);
  options.start = toOptimizerVector(input.parameters);
  run.result = optimize(run.box, meshQualityObjective(input, options.threads), options);
  run.best = run.result.history.empty() ? input.parameters : toMeshingParameters(run.result.best);
  return run;
}

}  // namespace passageMesh
