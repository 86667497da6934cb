#include "passageMesh/mesh/ArcLengthTable.hpp"

#include <algorithm>
#include <stdexcept>

namespace passageMesh {

ArcLengthTable::ArcLengthTable(std::vector<double> parameters,
                               const std::vector<Eigen::Vector2d>& points)
    : t_(std::move(parameters)), s_(t_.size(), 0.0) {
  if (t_.size() < 2 || points.size() != t_.size())
    throw std::invalid_argument("ArcLengthTable: need matching parameters and points, at least 2");
  for (std::size_t k = 1; k < t_.size(); ++k) s_[k] = s_[k - 1] + (points[k] - points[k - 1]).norm();
}

double ArcLengthTable::parameterAt(double s) const {
  if (s <= 0) return t_.front();
  if (s >= s_.back()) return t_.back();
  const auto it = std::upper_bound(s_.begin(), s_.end(), s);
  const std::size_t k = static_cast<std::size_t>(it - s_.begin());
  const double f = (s - s_[k - 1]) / (s_[k] - s_[k - 1]);
  return t_[k - 1] + f * (t_[k] - t_[k - 1]);
}

}  // namespace passageMesh
