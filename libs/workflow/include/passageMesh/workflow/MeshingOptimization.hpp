#pragma once
// The best meshing parameters for one case by iteration (iterOptimize, issue 5): the
// optimiser (Optimizer.hpp) maximises the mesh quality Q (MeshQualityObjective.hpp) over
// the range box of method.md section 1 for the case's chord, starting from the case's
// own meshing parameters (meshDict.xml or the defaults), so the first evaluation is the
// start and the best is never worse than it.
#include "passageMesh/optimize/BoxProblem.hpp"
#include "passageMesh/optimize/Optimizer.hpp"
#include "passageMesh/passage/PassageCase.hpp"

namespace passageMesh {

struct MeshingOptimization {
  BoxProblem box;               // the meshing-parameter box (history files name its dimensions)
  OptimizationResult result;    // every evaluation; result.stopped when the stop flag ended it
  MeshingParameters best;       // the best evaluated (the start when nothing was evaluated)

  double startQuality() const;  // Q of the first evaluation, the start; NaN when none
  bool foundValidMesh() const;  // a Q above invalidMeshQuality was reached
  long bestEvaluation() const;  // the index of the first evaluation of the best Q; -1 when none
};

// options.start is replaced by the case's parameters; options.threads (0 = all cores)
// also sets how many meshes are built at once. Throws std::invalid_argument for an
// unknown method or a budget below 1 before anything is evaluated.
MeshingOptimization optimizeMeshingParameters(const PassageCase& input, OptimizerOptions options);

}  // namespace passageMesh
