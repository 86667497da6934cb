#include "passageMesh/passage/PassageSampler.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "passageMesh/blade/BladeSampler.hpp"

namespace passageMesh {

namespace {

double between(std::mt19937_64& rng, double a, double b) { return a + (b - a) * uniform01(rng); }

}  // namespace

PassageCondition sampleCondition(double chord, std::mt19937_64& rng) {
  using R = PassageConditionRange;
  PassageCondition c;
  c.pitch = between(rng, R::pitchMin, R::pitchMax) * chord;
  c.xIn = between(rng, R::xInMin, R::xInMax) * chord;
  c.xOut = between(rng, R::xOutMin, R::xOutMax) * chord;
  c.nO = static_cast<int>(std::lround(between(rng, R::nOMin, R::nOMax)));
  c.firstCellHeight = between(rng, R::firstCellHeightMin, R::firstCellHeightMax) * chord;
  return c;
}

MeshingParameters sampleMeshingParameters(double chord, std::mt19937_64& rng) {
  // The method's eight only (the random stream of every sweep and validation set stays
  // that of the eight-parameter table); the splits stay at 0, the method's outer loop.
  auto x = MeshingParameters{}.toArray();
  const auto lo = MeshingParameters::lowerBounds(chord), hi = MeshingParameters::upperBounds(chord);
  for (int k = 0; k < MeshingParameters::methodSize; ++k) x[k] = between(rng, lo[k], hi[k]);
  return MeshingParameters::fromArray(x);
}

std::vector<PassageDraw> samplePassages(int count, std::uint64_t seed) {
  BladeSampler sampler(BladeParameterRange::readDefault(), seed);
  std::mt19937_64 rng(seed + 1);
  std::vector<PassageDraw> draws(static_cast<std::size_t>(std::max(0, count)));
  for (auto& d : draws) {
    d.blade = sampler.next();
    d.condition = sampleCondition(d.blade.chord, rng);
    d.parameters = sampleMeshingParameters(d.blade.chord, rng);
  }
  return draws;
}

}  // namespace passageMesh
