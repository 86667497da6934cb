#include "passageMesh/policy/PolicyScaling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace passageMesh {

namespace {

// The BSP entries that enter the state: all but xLe, yLe, chord (indices 0-2).
constexpr int firstShapeEntry = 3;
constexpr int shapeEntries = BladeParameters::size - firstShapeEntry;
static_assert(shapeEntries + 5 == policyStateSize);

double toUnit(double value, double lower, double upper) {
  if (upper <= lower) return 0.0;
  return 2.0 * (value - lower) / (upper - lower) - 1.0;
}

double fromUnit(double unit, double lower, double upper) {
  return lower + 0.5 * (std::clamp(unit, -1.0, 1.0) + 1.0) * (upper - lower);
}

// Ranges of the condition entries, lengths in chords.
struct ConditionEntry {
  const char* name;
  double lower, upper;
};
constexpr std::array<ConditionEntry, 5> conditionEntries{{
    {"pitch", PassageConditionRange::pitchMin, PassageConditionRange::pitchMax},
    {"xIn", PassageConditionRange::xInMin, PassageConditionRange::xInMax},
    {"xOut", PassageConditionRange::xOutMin, PassageConditionRange::xOutMax},
    {"nO", PassageConditionRange::nOMin, PassageConditionRange::nOMax},
    {"firstCellHeight", PassageConditionRange::firstCellHeightMin,
     PassageConditionRange::firstCellHeightMax},
}};

}  // namespace

const std::array<std::string, policyStateSize>& policyStateNames() {
  static const std::array<std::string, policyStateSize> names = [] {
    std::array<std::string, policyStateSize> n;
    const auto& bsp = BladeParameters::names();
    for (int k = 0; k < shapeEntries; ++k) n[k] = bsp[firstShapeEntry + k];
    n[1] = "thetaLeMinusStagger";  // range coordinates (etc/bladeParameterRange.xml)
    n[2] = "thetaTeMinusStagger";
    for (int k = 0; k < 5; ++k) n[shapeEntries + k] = conditionEntries[k].name;
    return n;
  }();
  return names;
}

PolicyStateScaling policyStateScaling(const BladeParameterRange& range, EdgeRadiusScale edgeRadii) {
  PolicyStateScaling b;
  for (int k = 0; k < shapeEntries; ++k) {
    b.lower[k] = range.lower[firstShapeEntry + k];
    b.upper[k] = range.upper[firstShapeEntry + k];
  }
  for (int k = 0; k < 5; ++k) {
    b.lower[shapeEntries + k] = conditionEntries[k].lower;
    b.upper[shapeEntries + k] = conditionEntries[k].upper;
  }
  if (edgeRadii == EdgeRadiusScale::logarithmic)
    for (int k : {BladeParameters::radiusLeIndex, BladeParameters::radiusTeIndex}) {
      const int entry = k - firstShapeEntry;
      if (!(b.lower[entry] > 0) || !(b.upper[entry] > b.lower[entry]))
        throw std::invalid_argument("policy state: the logarithmic scale of " + policyStateNames()[entry] +
                                    " needs 0 < lower < upper");
      b.logarithmic[entry] = true;
    }
  return b;
}

PolicyState policyState(const BladeParameters& blade, const PassageCondition& condition,
                        const PolicyStateScaling& scaling) {
  const auto v = BladeParameterRange::toRangeCoordinates(blade);
  const double c = blade.chord;
  PolicyState values;
  for (int k = 0; k < shapeEntries; ++k) values[k] = v[firstShapeEntry + k];
  const std::array<double, 5> conditionValues{condition.pitch / c, condition.xIn / c, condition.xOut / c,
                                              static_cast<double>(condition.nO),
                                              condition.firstCellHeight / c};
  for (int k = 0; k < 5; ++k) values[shapeEntries + k] = conditionValues[k];
  PolicyState s;
  for (int k = 0; k < policyStateSize; ++k) {
    if (!scaling.logarithmic[k]) {
      s[k] = toUnit(values[k], scaling.lower[k], scaling.upper[k]);
      continue;
    }
    // A radius of 0 or less (a fitted blade can give one) sits far below the range: a
    // millionth of the lower bound keeps the state finite and stateOutsideTraining names it.
    const double positive = std::max(values[k], 1e-6 * scaling.lower[k]);
    s[k] = toUnit(std::log(positive), std::log(scaling.lower[k]), std::log(scaling.upper[k]));
  }
  return s;
}

PolicyState policyState(const BladeParameters& blade, const PassageCondition& condition) {
  static const PolicyStateScaling scaling = policyStateScaling(BladeParameterRange::readDefault());
  return policyState(blade, condition, scaling);
}

std::vector<std::string> stateOutsideTraining(const PolicyState& state) {
  std::vector<std::string> lines;
  const double tolerance = 1e-9;  // a value on the range's edge is inside
  for (int k = 0; k < policyStateSize; ++k) {
    if (std::abs(state[k]) <= 1.0 + tolerance) continue;
    char text[160];
    std::snprintf(text, sizeof text, "%s is outside the policy's training range (%.4g in [-1, 1] units)",
                  policyStateNames()[k].c_str(), state[k]);
    lines.emplace_back(text);
  }
  return lines;
}

PolicyAction policyAction(const MeshingParameters& parameters, double chord) {
  PolicyAction a;
  const auto v = parameters.toArray();
  const auto lo = MeshingParameters::lowerBounds(chord), hi = MeshingParameters::upperBounds(chord);
  for (int k = 0; k < policyActionSize; ++k) a[k] = std::clamp(toUnit(v[k], lo[k], hi[k]), -1.0, 1.0);
  return a;
}

MeshingParameters meshingParametersOf(const PolicyAction& action, double chord) {
  std::array<double, MeshingParameters::size> v;
  const auto lo = MeshingParameters::lowerBounds(chord), hi = MeshingParameters::upperBounds(chord);
  for (int k = 0; k < policyActionSize; ++k) {
    if (!std::isfinite(action[k]))
      throw std::invalid_argument("the policy's action for " + MeshingParameters::names()[k] + " is not a number");
    v[k] = fromUnit(action[k], lo[k], hi[k]);
  }
  return MeshingParameters::fromArray(v);
}

}  // namespace passageMesh
