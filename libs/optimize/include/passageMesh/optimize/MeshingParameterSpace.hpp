#pragma once
// The meshing parameters as the optimiser's search space (method.md section 1): the range
// box for a chord, nT integer, in the order of MeshingParameters::toArray.
#include <Eigen/Core>

#include "passageMesh/optimize/BoxProblem.hpp"
#include "passageMesh/passage/MeshingParameters.hpp"

namespace passageMesh {

BoxProblem meshingParameterProblem(double chord);

Eigen::VectorXd toOptimizerVector(const MeshingParameters& p);
// Throws std::invalid_argument unless v has MeshingParameters::size entries; nT rounded.
MeshingParameters toMeshingParameters(const Eigen::VectorXd& v);

}  // namespace passageMesh
