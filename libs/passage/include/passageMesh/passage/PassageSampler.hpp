#pragma once
// Random blade passages over the method's whole ranges (method.md section 1): a blade from
// the BSP box, a condition from PassageConditionRange and meshing parameters from their
// box, all uniform. The robustness sweep (bench/meshRobustnessSweep, MeshRobustness test)
// meshes them; the policy trainer draws its conditions the same way. Deterministic for a
// seed on every platform (uniform01 on mt19937_64).
#include <cstdint>
#include <random>
#include <vector>

#include "passageMesh/blade/BladeParameters.hpp"
#include "passageMesh/passage/MeshingParameters.hpp"
#include "passageMesh/passage/PassageCondition.hpp"

namespace passageMesh {

// Uniform in PassageConditionRange for a blade of this chord [m]; nO rounded.
PassageCondition sampleCondition(double chord, std::mt19937_64& rng);

// Uniform in the box of the method's eight meshing parameters (MeshingParameters::lowerBounds
// .. upperBounds); nT rounded; splitIn, splitOut 0.
MeshingParameters sampleMeshingParameters(double chord, std::mt19937_64& rng);

struct PassageDraw {
  BladeParameters blade;
  PassageCondition condition;
  MeshingParameters parameters;
};

// `count` draws: blades from BladeSampler(readDefault(), seed), conditions and parameters
// from mt19937_64(seed + 1), in that order per draw.
std::vector<PassageDraw> samplePassages(int count, std::uint64_t seed);

}  // namespace passageMesh
