#include "passageMesh/optimize/SyntheticObjectives.hpp"

#include <algorithm>
#include <cmath>

#include "passageMesh/optimize/MeshingParameterSpace.hpp"

namespace passageMesh {

namespace {

// yIn, yOut, alphaCamber, betaIn, betaOut, nT, gammaLe, gammaTe: away from the centre
// (a method cannot win by starting there) and from the bounds.
MeshingParameters optimumParameters() {
  MeshingParameters p;
  p.yIn = 0.12;
  p.yOut = -0.23;
  p.alphaCamber = 0.7;
  p.betaIn = 0.35;
  p.betaOut = 0.6;
  p.nT = 437;
  p.gammaLe = 1.8;
  p.gammaTe = 0.9;
  return p;
}

// The box, the optimum, and a function of the unit-cube point and the optimum's.
SyntheticProblem makeProblem(const std::string& name,
                             double (*valueInUnitCube)(const Eigen::VectorXd& u, const Eigen::VectorXd& a)) {
  SyntheticProblem s;
  s.name = name;
  // The box of the method's eight meshing parameters (docs/benchmarks.md's figures are
  // for it; the mesher's splits are not part of these problems).
  constexpr int n = MeshingParameters::methodSize;
  s.box = meshingParameterProblem(1.0);
  s.box.lower.conservativeResize(n);
  s.box.upper.conservativeResize(n);
  s.box.integer.resize(n);
  s.box.names.resize(n);
  s.optimum = toOptimizerVector(optimumParameters()).head(n);
  const BoxProblem box = s.box;
  const Eigen::VectorXd a = box.toUnit(s.optimum);
  s.objective = [box, a, valueInUnitCube](const Eigen::VectorXd& x) { return valueInUnitCube(box.toUnit(x), a); };
  return s;
}

double peak(const Eigen::VectorXd& u, const Eigen::VectorXd& centre) {
  return 1 / (1 + 10 * (u - centre).squaredNorm());
}

}  // namespace

SyntheticProblem shiftedBowl() {
  return makeProblem("shiftedBowl", [](const Eigen::VectorXd& u, const Eigen::VectorXd& a) { return peak(u, a); });
}

SyntheticProblem twoPeaksWithInvalidRegion() {
  return makeProblem("twoPeaksWithInvalidRegion", [](const Eigen::VectorXd& u, const Eigen::VectorXd& a) {
    // a[0] - a[1] = 0.35: the optimum is 0.1 from the first region's edge.
    if (u[0] - u[1] > 0.45 || u[6] + u[7] < 0.15) return -1.0;
    // The decoy is near the centre of the box, the first start of every method.
    const Eigen::VectorXd decoy = (Eigen::VectorXd(8) << 0.45, 0.55, 0.4, 0.6, 0.45, 0.55, 0.5, 0.5).finished();
    return std::max(peak(u, a), 0.8 * peak(u, decoy));
  });
}

SyntheticProblem shiftedRastrigin() {
  return makeProblem("shiftedRastrigin", [](const Eigen::VectorXd& u, const Eigen::VectorXd& a) {
    const Eigen::ArrayXd d = (u - a).array();
    return 1 - (d.square() + 0.05 * (1 - (10 * M_PI * d).cos())).mean();
  });
}

SyntheticProblem bowlInNarrowValidTube() {
  return makeProblem("bowlInNarrowValidTube", [](const Eigen::VectorXd& u, const Eigen::VectorXd& a) {
    const Eigen::VectorXd centre = Eigen::VectorXd::Constant(u.size(), 0.5), axis = a - centre;
    const double t = std::clamp((u - centre).dot(axis) / axis.squaredNorm(), 0.0, 1.0);
    if ((u - centre - t * axis).norm() > 0.08) return -1.0;
    return peak(u, a);
  });
}

std::vector<SyntheticProblem> syntheticProblems() {
  return {shiftedBowl(), twoPeaksWithInvalidRegion(), shiftedRastrigin(), bowlInNarrowValidTube()};
}

}  // namespace passageMesh
