#pragma once
// The search space of an optimisation: a box, lower[k] <= x[k] <= upper[k], some of whose
// dimensions take integer values only (nT). The methods search the box scaled to the unit
// cube, where every dimension has the same length, and the objective sees the point
// clipped into the box with the integer dimensions rounded (evaluatedPoint).
#include <Eigen/Core>
#include <random>
#include <string>
#include <vector>

namespace passageMesh {

struct BoxProblem {
  Eigen::VectorXd lower, upper;
  std::vector<bool> integer;  // per dimension; empty = none
  std::vector<std::string> names;  // per dimension, for history files; empty = x0, x1, ...

  int dimension() const { return static_cast<int>(lower.size()); }
  bool isInteger(int k) const { return !integer.empty() && integer[k]; }
  std::string name(int k) const;

  // Throws std::invalid_argument unless the sizes agree and lower[k] < upper[k] for every
  // k (an integer dimension must hold at least two integers).
  void check() const;

  // Between the box and the unit cube.
  Eigen::VectorXd toUnit(const Eigen::VectorXd& x) const;
  Eigen::VectorXd fromUnit(const Eigen::VectorXd& u) const;

  // What the objective is given for x: clipped into the box, integer dimensions rounded
  // to the nearest integer inside it.
  Eigen::VectorXd evaluatedPoint(const Eigen::VectorXd& x) const;

  Eigen::VectorXd centre() const { return (lower + upper) / 2; }
  // Uniformly distributed in the box (before rounding), from the project's uniform01.
  Eigen::VectorXd randomPoint(std::mt19937_64& rng) const;
};

}  // namespace passageMesh
