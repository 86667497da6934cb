#pragma once
// A trained policy on disk and in use (docs/case-format.md "Policy files"):
//   NAME.xml  its description: format version, the actor file's name, the layers, the
//             state and action names in order with the ranges (and, for the state, the
//             linear or logarithmic scale) that map them to [-1, 1]
//   NAME.pt   the actor's weights, LibTorch's own serialisation; Python reads them by name
//             with torch.jit.load("NAME.pt").state_dict() (layers.0.weight, ...)
// or an ensemble of such policies:
//   NAME.xml  format "passageMesh policy ensemble 1" and <members>, the member policies'
//             .xml files (relative to it); the ensemble's action is the mean of the
//             members' actions (scaled units), each member one forward pass
// policyMesh loads it and maps a passage to its meshing parameters in one forward pass
// (one per member).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "passageMesh/blade/BladeParameters.hpp"
#include "passageMesh/passage/MeshingParameters.hpp"
#include "passageMesh/passage/PassageCondition.hpp"
#include "passageMesh/policy/ActorCritic.hpp"
#include "passageMesh/policy/PolicyScaling.hpp"

namespace passageMesh {

// What policyTrain records beside the weights.
struct PolicyProvenance {
  long episodes = 0;              // episodes of the run that wrote the file (a run started
                                  // with -actorFrom does not count its start's)
  double validationMeanReward = 0;  // their validation score
  std::string command;            // how they were trained
};

// Writes NAME.pt (the learner's actor) and NAME.xml, each atomically, the .pt first;
// `scaling` is the state scaling the actor was trained with.
void writePolicyFiles(const std::filesystem::path& xmlFile, const ActorCritic& learner,
                      const PolicyStateScaling& scaling, const PolicyProvenance& provenance);

class Policy {
 public:
  // Reads NAME.xml and the actor file it names, or an ensemble's member files. A missing or
  // corrupt file, a layout or scaling that is not this build's, or members that scale the
  // state differently, is an InputError naming the file.
  static Policy load(const std::filesystem::path& xmlFile);
  ~Policy();
  Policy(Policy&&) noexcept;
  Policy& operator=(Policy&&) noexcept;

  PolicyAction act(const PolicyState& state) const;  // one forward pass per member, no noise
  // The actions to mesh with, in turn, until one mesh is valid: act(state) first, then
  // (an ensemble's) each member's own action in the members' order, a member without the
  // splits giving them at 0. Why: the mean of the members' actions can fold a passage that
  // each member alone meshes (docs/policy.md "Members' own actions where the mean folds").
  // A single actor's list is act(state) alone.
  std::vector<PolicyAction> actionsInTurn(const PolicyState& state) const;
  // The passage's state under this policy's own scaling (its file's <stateScale>).
  PolicyState state(const BladeParameters& blade, const PassageCondition& condition) const;
  const PolicyStateScaling& stateScaling() const;
  MeshingParameters meshingParameters(const BladeParameters& blade,
                                      const PassageCondition& condition) const;
  const NetworkLayout& layout() const;  // the first member's
  const std::filesystem::path& actorFile() const;  // the first member's weights (.pt)
  // An ensemble's: the members' episodes summed (their files' counts, not a training
  // length), its file's <validationMeanReward> and <command> (0 and empty where it has none).
  const PolicyProvenance& provenance() const;
  int memberCount() const;  // 1 for a single actor

 private:
  Policy();
  // A member's own action (the entries from `size` on, which it lacks, at the method's
  // outer loop's) and how many of the actions its network gives.
  struct MemberAction {
    PolicyAction action;
    int size;
  };
  std::vector<MemberAction> memberActions(const PolicyState& state) const;
  static PolicyAction meanAction(const std::vector<MemberAction>& members);
  struct Actor;
  struct Members;
  std::unique_ptr<Members> members_;
};

// etc/policy/policy.xml (the shipped policy).
std::filesystem::path defaultPolicyFile();

}  // namespace passageMesh
