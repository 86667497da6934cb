#include "passageMesh/blade/BladeSampler.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "passageMesh/blade/BladeShape.hpp"
#include "passageMesh/blade/BladeValidity.hpp"
#include "passageMesh/core/Dictionary.hpp"
#include "passageMesh/core/EtcFiles.hpp"
#include "passageMesh/core/InputError.hpp"

namespace passageMesh {

namespace {

// The range file's key for each parameter: the camber angles are relative to the stagger.
std::vector<std::string> rangeKeys() {
  const auto& names = BladeParameters::names();
  std::vector<std::string> keys(names.begin(), names.end());
  keys[4] = "thetaLeMinusStagger";
  keys[5] = "thetaTeMinusStagger";
  return keys;
}

}  // namespace

BladeParameterRange BladeParameterRange::read(const std::filesystem::path& file) {
  const auto names = rangeKeys();
  const Dictionary dict = Dictionary::read(file, "bladeParameterRange", names);
  BladeParameterRange range;
  for (int k = 0; k < BladeParameters::size; ++k) {
    std::istringstream words(dict.text(names[k]));
    std::string a, b, extra;
    words >> a >> b >> extra;
    double lo = 0, hi = 0;
    if (!parseFiniteDouble(a, lo) || !parseFiniteDouble(b, hi) || !extra.empty() || lo > hi)
      throw InputError(file.string(), dict.line(names[k]),
                       "<" + names[k] + ">: expected 'min max' with min <= max");
    range.lower[k] = lo;
    range.upper[k] = hi;
  }
  return range;
}

BladeParameterRange BladeParameterRange::readDefault() {
  return read(findEtcFile("bladeParameterRange.xml"));
}

std::array<double, BladeParameters::size> BladeParameterRange::toRangeCoordinates(
    const BladeParameters& p) {
  auto v = p.toArray();
  v[4] -= p.stagger;
  v[5] -= p.stagger;
  return v;
}

BladeParameters BladeParameterRange::fromRangeCoordinates(
    std::array<double, BladeParameters::size> v) {
  v[4] += v[3];
  v[5] += v[3];
  return BladeParameters::fromArray(v);
}

bool BladeParameterRange::contains(const BladeParameters& p) const {
  const auto v = toRangeCoordinates(p);
  for (int k = 0; k < BladeParameters::size; ++k)
    if (v[k] < lower[k] || v[k] > upper[k]) return false;
  return true;
}

double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

BladeSampler::BladeSampler(BladeParameterRange range, std::uint64_t seed, EdgeRadiusDraw edgeRadii)
    : range_(range), rng_(seed), edgeRadii_(edgeRadii) {
  if (edgeRadii_ == EdgeRadiusDraw::halfLogUniform)
    for (int k : {BladeParameters::radiusLeIndex, BladeParameters::radiusTeIndex})
      if (!(range_.lower[k] > 0))
        throw std::invalid_argument("blade sampler: a log-uniform edge radius needs a positive lower bound, not " +
                                    std::to_string(range_.lower[k]));
}

BladeParameters BladeSampler::next(int maxTries) {
  for (int attempt = 0; attempt < maxTries; ++attempt) {
    std::array<double, BladeParameters::size> v;
    for (int k = 0; k < BladeParameters::size; ++k)
      v[k] = range_.lower[k] + (range_.upper[k] - range_.lower[k]) * uniform01(rng_);
    // The coins come after the box's draws, so uniform draws keep their old sequence.
    if (edgeRadii_ == EdgeRadiusDraw::halfLogUniform)
      for (int k : {BladeParameters::radiusLeIndex, BladeParameters::radiusTeIndex}) {
        const double u = uniform01(rng_);
        if (uniform01(rng_) < 0.5)
          v[k] = range_.lower[k] * std::pow(range_.upper[k] / range_.lower[k], u);
      }
    ++drawn_;
    const BladeParameters p = BladeParameterRange::fromRangeCoordinates(v);
    if (checkBladeValidity(BladeShape(p)).valid) {
      ++accepted_;
      return p;
    }
  }
  throw std::runtime_error("blade sampler: no valid blade in " + std::to_string(maxTries) +
                           " draws; is the range box sensible?");
}

}  // namespace passageMesh
