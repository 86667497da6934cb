#pragma once
// Cheap objectives with known maxima in the box of the method's eight meshing parameters (chord 1, nT integer),
// standing in for the mesh quality Q in the optimiser's tests and benchmark. Each has its
// maximum 1 at the same point inside the box, with nT = 437 an integer.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "passageMesh/optimize/BoxProblem.hpp"
#include "passageMesh/optimize/Objective.hpp"

namespace passageMesh {

struct SyntheticProblem {
  std::string name;
  BoxProblem box;
  PointObjective objective;
  Eigen::VectorXd optimum;  // where the maximum, 1, is
};

// 1 / (1 + 10 r^2), r the distance from the optimum in the box scaled to the unit cube.
SyntheticProblem shiftedBowl();
// The bowl, a second peak of height 0.8 near the centre of the box, whose basin holds the
// centre (a local method started there ends on it), and regions returning -1 as invalid
// meshes do, one of them reaching close to the optimum.
SyntheticProblem twoPeaksWithInvalidRegion();
// 1 - mean of d^2 + 0.05 (1 - cos(10 pi d)) over the unit-cube offsets d: a bowl with
// ripples, five local maxima across each dimension.
SyntheticProblem shiftedRastrigin();

// The bowl, valid only in a narrow tube (radius 0.08 of the unit cube) from the box
// centre, where every method starts, to the optimum; -1 (an invalid mesh) everywhere
// else, about 99.99 % of the box. Like the mesh quality of a real blade, where only
// parameters near a working set give a valid mesh (docs/optimization.md).
SyntheticProblem bowlInNarrowValidTube();

std::vector<SyntheticProblem> syntheticProblems();

}  // namespace passageMesh
