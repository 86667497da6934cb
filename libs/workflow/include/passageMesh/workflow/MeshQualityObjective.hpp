#pragma once
// The mesh quality Q as the optimiser's objective (iterOptimize, issue 5): a point of the
// meshing-parameter box (MeshingParameterSpace.hpp) -> the HOH mesh of the case's blade
// and condition (buildHohMesh) -> its Q (computeMeshQuality; invalidMeshQuality, -1, for
// a folded mesh). In-process: no disk I/O, nothing written.
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/optimize/Objective.hpp"
#include "passageMesh/passage/PassageCase.hpp"

namespace passageMesh {

// Q of the case's mesh with these parameters. Safe to call from several threads at once:
// buildHohMesh has no shared state and each thread measures with its own workspace.
// `options`: the mesher's (buildHohMesh's defaults, as ellipticMesh and policyMesh mesh).
double meshQualityOf(const PassageCase& input, const MeshingParameters& parameters,
                     const HohMeshOptions& options = {});

// Q of an optimiser point (toMeshingParameters order). The objective keeps its own copy
// of the case.
PointObjective meshQualityPointObjective(const PassageCase& input);

// The same on up to `threads` threads (0 = all cores), one mesh per thread at a time;
// values by index, so a run does not depend on the thread count.
BatchObjective meshQualityObjective(const PassageCase& input, int threads);

}  // namespace passageMesh
