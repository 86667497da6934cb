#pragma once
// A curve's arc length tabulated at increasing parameter values (the chords of the
// sampled polygon), for placing nodes by length: parameterAt inverts the table by linear
// interpolation between samples.
#include <Eigen/Core>
#include <vector>

namespace passageMesh {

class ArcLengthTable {
 public:
  // `points[k]` is the curve at `parameters[k]`; the parameters increase.
  ArcLengthTable(std::vector<double> parameters, const std::vector<Eigen::Vector2d>& points);

  double length() const { return s_.back(); }
  // The parameter at arc length s from the first sample, clamped to the ends.
  double parameterAt(double s) const;

 private:
  std::vector<double> t_, s_;
};

}  // namespace passageMesh
