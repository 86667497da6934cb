#include "passageMesh/optimize/BoxProblem.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "passageMesh/blade/BladeSampler.hpp"  // uniform01

namespace passageMesh {

std::string BoxProblem::name(int k) const {
  if (!names.empty()) return names[k];
  std::string generic = "x";  // (not "x" + ...: g++ 12 warns falsely about it, -Wrestrict)
  return generic += std::to_string(k);
}

void BoxProblem::check() const {
  const auto n = static_cast<std::size_t>(dimension());
  if (n == 0 || static_cast<std::size_t>(upper.size()) != n ||
      (!integer.empty() && integer.size() != n) || (!names.empty() && names.size() != n))
    throw std::invalid_argument("optimize: the box's lower, upper, integer and names sizes differ");
  for (int k = 0; k < dimension(); ++k) {
    const bool empty = isInteger(k) ? std::floor(upper[k]) - std::ceil(lower[k]) < 1
                                    : !(lower[k] < upper[k]);
    if (empty)
      throw std::invalid_argument("optimize: dimension " + name(k) + " has an empty range [" +
                                  std::to_string(lower[k]) + ", " + std::to_string(upper[k]) + "]");
  }
}

Eigen::VectorXd BoxProblem::toUnit(const Eigen::VectorXd& x) const {
  return ((x - lower).array() / (upper - lower).array()).matrix();
}

Eigen::VectorXd BoxProblem::fromUnit(const Eigen::VectorXd& u) const {
  return lower + (u.array() * (upper - lower).array()).matrix();
}

Eigen::VectorXd BoxProblem::evaluatedPoint(const Eigen::VectorXd& x) const {
  Eigen::VectorXd p = x.cwiseMax(lower).cwiseMin(upper);
  for (int k = 0; k < dimension(); ++k)
    if (isInteger(k)) p[k] = std::clamp(std::round(p[k]), std::ceil(lower[k]), std::floor(upper[k]));
  return p;
}

Eigen::VectorXd BoxProblem::randomPoint(std::mt19937_64& rng) const {
  Eigen::VectorXd u(dimension());
  for (int k = 0; k < dimension(); ++k) u[k] = uniform01(rng);
  return fromUnit(u);
}

}  // namespace passageMesh
