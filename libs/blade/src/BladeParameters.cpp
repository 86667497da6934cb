#include "passageMesh/blade/BladeParameters.hpp"

#include <algorithm>

namespace passageMesh {

std::array<double, BladeParameters::size> BladeParameters::toArray() const {
  std::array<double, size> v{xLe,     yLe,     chord,    stagger,  thetaLe,
                             thetaTe, distLe,  distTe,   radiusLe, radiusTe};
  std::copy(thicknessUpper.begin(), thicknessUpper.end(), v.begin() + 10);
  std::copy(thicknessLower.begin(), thicknessLower.end(), v.begin() + 16);
  return v;
}

BladeParameters BladeParameters::fromArray(const double* v) {
  BladeParameters p;
  p.xLe = v[0];
  p.yLe = v[1];
  p.chord = v[2];
  p.stagger = v[3];
  p.thetaLe = v[4];
  p.thetaTe = v[5];
  p.distLe = v[6];
  p.distTe = v[7];
  p.radiusLe = v[8];
  p.radiusTe = v[9];
  std::copy(v + 10, v + 16, p.thicknessUpper.begin());
  std::copy(v + 16, v + 22, p.thicknessLower.begin());
  return p;
}

BladeParameters BladeParameters::fromArray(const std::array<double, size>& values) {
  return fromArray(values.data());
}

const std::array<std::string, BladeParameters::size>& BladeParameters::names() {
  static const std::array<std::string, size> n{
      "xLe",             "yLe",             "chord",           "stagger",
      "thetaLe",         "thetaTe",         "distLe",          "distTe",
      "radiusLe",        "radiusTe",        "thicknessUpper1", "thicknessUpper2",
      "thicknessUpper3", "thicknessUpper4", "thicknessUpper5", "thicknessUpper6",
      "thicknessLower1", "thicknessLower2", "thicknessLower3", "thicknessLower4",
      "thicknessLower5", "thicknessLower6"};
  return n;
}

}  // namespace passageMesh
