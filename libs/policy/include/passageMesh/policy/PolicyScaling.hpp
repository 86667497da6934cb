#pragma once
// The policy's state and action, both scaled to [-1, 1] (method.md section 6; docs/policy.md).
//
// State (24 values): the blade's shape parameters without position and size (xLe, yLe and
// chord are left out: Q does not change when a passage is moved or scaled, method.md
// section 1), the camber angles relative to the stagger as etc/bladeParameterRange.xml
// gives them, then the condition in chords: pitch, xIn, xOut, nO, firstCellHeight. Each
// value is mapped from its range (the BSP box, PassageConditionRange) to [-1, 1]: linearly,
// except the edge radii, whose range spans 2.5-3.5 decades: those are mapped linearly in
// their logarithm (policy format 2), so that a sharp edge (1e-4 chord) and a sharper one
// are told apart (format 1, the linear map, crowds all sharp edges near -1).
// Action (10 values): the meshing parameters in MeshingParameters::table() order, each
// mapped linearly from its range (lengths in chords) to [-1, 1]. Policy files written before
// the splits (splitIn, splitOut) were meshing parameters have the method's eight only; they
// are still read, and their meshes have the splits at 0 (Policy::act).
#include <array>
#include <string>
#include <vector>

#include "passageMesh/blade/BladeParameters.hpp"
#include "passageMesh/blade/BladeSampler.hpp"
#include "passageMesh/passage/MeshingParameters.hpp"
#include "passageMesh/passage/PassageCondition.hpp"

namespace passageMesh {

constexpr int policyStateSize = 24;
constexpr int policyActionSize = MeshingParameters::size;
using PolicyState = std::array<double, policyStateSize>;
using PolicyAction = std::array<double, policyActionSize>;

// The state's names in order ("stagger", ..., "pitch", ..., "firstCellHeight").
const std::array<std::string, policyStateSize>& policyStateNames();

// How each state value is scaled: its range in its own units (range coordinates of the
// BSP box, then the condition in chords; etc/bladeParameterRange.xml,
// PassageConditionRange), the value at `lower` scaling to -1 and at `upper` to +1, and
// whether that map is linear in the logarithm of the value (logarithmic) or in the value.
struct PolicyStateScaling {
  PolicyState lower, upper;
  std::array<bool, policyStateSize> logarithmic{};
};
enum class EdgeRadiusScale { linear, logarithmic };
// The scaling of a range box; the edge radii as `edgeRadii` says (logarithmic: this
// build's policies; linear: policy files of format 1). Throws std::invalid_argument where
// a logarithmic entry's lower bound is not positive.
PolicyStateScaling policyStateScaling(const BladeParameterRange& range,
                                      EdgeRadiusScale edgeRadii = EdgeRadiusScale::logarithmic);

// The state of a passage under a scaling.
PolicyState policyState(const BladeParameters& blade, const PassageCondition& condition,
                        const PolicyStateScaling& scaling);
// The same with this build's scaling of etc/bladeParameterRange.xml (read once).
PolicyState policyState(const BladeParameters& blade, const PassageCondition& condition);

// One line per state value outside [-1, 1]: the policy was not trained there.
std::vector<std::string> stateOutsideTraining(const PolicyState& state);

// The action of a set of meshing parameters for a blade of this chord, and back. Action
// values outside [-1, 1] are clipped; nT is rounded; a non-finite action value (a
// diverged network) throws std::invalid_argument naming the parameter.
PolicyAction policyAction(const MeshingParameters& parameters, double chord);
MeshingParameters meshingParametersOf(const PolicyAction& action, double chord);

}  // namespace passageMesh
