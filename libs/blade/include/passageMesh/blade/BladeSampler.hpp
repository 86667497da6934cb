#pragma once
// Random valid blades from the BSP range box (etc/bladeParameterRange.xml): the policy
// trainer's blade source and the robustness tests' input. Deterministic for a seed on
// every platform (the uniform variates are built from mt19937_64 bits directly, not
// through std::uniform_real_distribution, whose algorithm the standard leaves open).
#include <array>
#include <cstdint>
#include <filesystem>
#include <random>

#include "passageMesh/blade/BladeParameters.hpp"

namespace passageMesh {

// A box in "range coordinates": the BSP array with thetaLe and thetaTe replaced by
// thetaLe - stagger and thetaTe - stagger (see etc/bladeParameterRange.xml).
struct BladeParameterRange {
  std::array<double, BladeParameters::size> lower{}, upper{};

  static std::array<double, BladeParameters::size> toRangeCoordinates(const BladeParameters& p);
  static BladeParameters fromRangeCoordinates(std::array<double, BladeParameters::size> v);

  static BladeParameterRange read(const std::filesystem::path& file);
  static BladeParameterRange readDefault();  // etc/bladeParameterRange.xml
  bool contains(const BladeParameters& p) const;
};

// Uniform variate in [0, 1) from 53 random bits.
double uniform01(std::mt19937_64& rng);

// How the sampler draws the two edge radii (radiusLe, radiusTe). Uniformly in the box,
// edges as sharp as STD10's and SIRT's (1e-4 chord) are under 3 % of the blades, and a
// policy trained on such draws learns what suits round edges (docs/policy.md). With
// halfLogUniform each radius is drawn log-uniformly in its range with probability 1/2
// (a coin per radius), else uniformly: sharp and round edges both come often.
enum class EdgeRadiusDraw { uniform, halfLogUniform };

class BladeSampler {
 public:
  BladeSampler(BladeParameterRange range, std::uint64_t seed,
               EdgeRadiusDraw edgeRadii = EdgeRadiusDraw::uniform);

  // A valid blade (checkBladeValidity); throws std::runtime_error after maxTries
  // rejections in a row.
  BladeParameters next(int maxTries = 100000);

  long drawn() const { return drawn_; }        // all draws, accepted and rejected
  long accepted() const { return accepted_; }
  const BladeParameterRange& range() const { return range_; }

 private:
  BladeParameterRange range_;
  std::mt19937_64 rng_;
  EdgeRadiusDraw edgeRadii_;
  long drawn_ = 0, accepted_ = 0;
};

}  // namespace passageMesh
