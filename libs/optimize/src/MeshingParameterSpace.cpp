#include "passageMesh/optimize/MeshingParameterSpace.hpp"

#include <stdexcept>

namespace passageMesh {

namespace {

Eigen::VectorXd toVector(const std::array<double, MeshingParameters::size>& a) {
  return Eigen::Map<const Eigen::VectorXd>(a.data(), MeshingParameters::size);
}

}  // namespace

BoxProblem meshingParameterProblem(double chord) {
  BoxProblem problem;
  problem.lower = toVector(MeshingParameters::lowerBounds(chord));
  problem.upper = toVector(MeshingParameters::upperBounds(chord));
  const auto& names = MeshingParameters::names();
  problem.names.assign(names.begin(), names.end());
  problem.integer.assign(MeshingParameters::size, false);
  for (int k = 0; k < MeshingParameters::size; ++k)
    problem.integer[k] = MeshingParameters::table()[k].integer;
  return problem;
}

Eigen::VectorXd toOptimizerVector(const MeshingParameters& p) { return toVector(p.toArray()); }

MeshingParameters toMeshingParameters(const Eigen::VectorXd& v) {
  if (v.size() != MeshingParameters::size)
    throw std::invalid_argument("optimize: a meshing parameter vector has " +
                                std::to_string(MeshingParameters::size) + " entries, not " +
                                std::to_string(v.size()));
  std::array<double, MeshingParameters::size> a;
  for (int k = 0; k < MeshingParameters::size; ++k) a[k] = v[k];
  return MeshingParameters::fromArray(a);
}

}  // namespace passageMesh
