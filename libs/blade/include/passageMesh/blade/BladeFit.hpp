#pragma once
// Fitting blade shape parameters to ordered profile points (bladeFit). The objective is
// the sum of squared point-to-curve distances; the foot points are eliminated by exact
// projection at every evaluation (variable projection), and Ceres' Levenberg-Marquardt
// solves for the 22 parameters with an analytic Jacobian (the control points are
// differentiated with ceres::Jet). The initial guess comes from the points: leading and
// trailing edge, chord, stagger, metal angles, thickness and edge radii.
#include <Eigen/Core>
#include <vector>

#include "passageMesh/blade/BladeParameters.hpp"
#include "passageMesh/blade/BladeValidity.hpp"

namespace passageMesh {

struct BladeFitOptions {
  int maxIterations = 60;  // Levenberg-Marquardt iterations per refined start and for the polish
  // Multi-start: edge camber angles relative to the guessed stagger [deg], every pair
  // fitted coarsely, then the best `refinedStarts` converged on all points.
  std::vector<double> leadingEdgeAngles{-75, -50, -25, 0, 25, 50, 75};
  std::vector<double> trailingEdgeAngles{-50, -25, 0, 25, 50};
  double gridSpacing = 25;  // [deg]; later rounds shift the grid by half of it
  // Rounds of the search, stopped once the maximum deviation of the points from the
  // fitted profile is within targetMaxDeviation (a fraction of the chord). Measured blades
  // never get that close (the parametrization cannot follow every detail) and take all
  // rounds; a blade the parametrization can represent usually stops after the first.
  int maxRounds = 4;
  double targetMaxDeviation = 1e-4;
  int coarsePoints = 100;    // subsample size of the coarse stage
  int refinePoints = 300;    // subsample size of the refined starts (the polish uses all)
  int coarseIterations = 15;
  int refinedStarts = 6;
  int threads = 0;  // for the starts; 0 = all cores (the result does not depend on it)
  // More starting points for the coarse stage (for example a previous fit).
  std::vector<BladeParameters> extraStarts;
  // The winner is refined minimising the sum of |distance|^finalPower (2 = no refinement).
  double finalPower = 4;
};

struct BladeFitResult {
  BladeParameters parameters;
  BladeParameters initialGuess;
  double meanDeviation = 0;  // of the input points from the fitted profile [m]
  double maxDeviation = 0;
  int maxDeviationPoint = -1;  // index in the points given to fitBlade
  int iterations = 0;          // Levenberg-Marquardt iterations, all starts together
  int starts = 0;  // coarse starts tried
  int rounds = 0;  // search rounds run
  double seconds = 0;
  BladeValidity validity;
};

// `points`: a counter-clockwise closed loop (orderBladePoints), flow towards +x.
BladeFitResult fitBlade(const std::vector<Eigen::Vector2d>& points,
                        const BladeFitOptions& options = {});

// The initial guess alone (exposed for tests and diagnostics).
BladeParameters guessBladeParameters(const std::vector<Eigen::Vector2d>& points);
// A guess with given camber angles at the edges [deg]: the edge points are placed where
// the profile is perpendicular to them.
BladeParameters guessBladeParameters(const std::vector<Eigen::Vector2d>& points,
                                     double thetaLe, double thetaTe);

}  // namespace passageMesh
