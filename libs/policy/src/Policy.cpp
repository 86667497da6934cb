#include "passageMesh/policy/Policy.hpp"

#include <array>
#include <cmath>
#include <sstream>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/Dictionary.hpp"
#include "passageMesh/core/EtcFiles.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/JoinedWords.hpp"
#include "passageMesh/core/ZipChecksums.hpp"
#include "passageMesh/policy/PolicyNetworks.hpp"
#include "TorchTensors.hpp"

namespace passageMesh {

namespace {

// Format 2 adds <stateScale> (linear or log per state value); format 1 files scale every
// state value linearly and are still read.
constexpr const char* policyFormat = "passageMesh policy 2";
constexpr const char* policyFormat1 = "passageMesh policy 1";
// An ensemble: the mean action of member policies (twenty-third session, docs/policy.md).
constexpr const char* ensembleFormat = "passageMesh policy ensemble 1";

const std::vector<std::string>& policyKeys() {
  static const std::vector<std::string> keys{
      "format", "actor", "hiddenLayers", "leakySlope", "layers", "stateNames", "stateLower",
      "stateUpper", "actionNames", "actionLower", "actionUpper", "trainedEpisodes",
      "validationMeanReward", "command"};
  return keys;
}

std::vector<std::string> policyKeysOfFormat2() {
  std::vector<std::string> keys = policyKeys();
  keys.push_back("stateScale");
  return keys;
}

// Either kind of file: an ensemble has format, members and optionally
// validationMeanReward and command.
std::vector<std::string> policyOrEnsembleKeys() {
  std::vector<std::string> keys = policyKeysOfFormat2();
  keys.push_back("members");
  return keys;
}

std::string scaleText(const PolicyStateScaling& scaling) {
  std::string text;
  for (int k = 0; k < policyStateSize; ++k) text += std::string(k ? " " : "") + (scaling.logarithmic[k] ? "log" : "linear");
  return text;
}

// Numbers to 17 significant digits, so that they read back bit for bit.
template <typename Container>
std::string numbersText(const Container& values) {
  std::ostringstream s;
  s.precision(17);
  bool first = true;
  for (const auto& v : values) {
    s << (first ? "" : " ") << v;
    first = false;
  }
  return s.str();
}

// This build's action layout for the first `size` meshing parameters (the state's comes
// from the trainer's or the file's scaling): all of them, or the method's eight of a
// policy written before the splits were parameters (policyActionSize's comment).
struct PolicyDescription {
  std::vector<double> actionLower, actionUpper;
  std::vector<std::string> actionNames;
  explicit PolicyDescription(int size = policyActionSize) {
    for (int k = 0; k < size; ++k) {
      actionLower.push_back(MeshingParameters::table()[k].lower);
      actionUpper.push_back(MeshingParameters::table()[k].upper);
      actionNames.push_back(MeshingParameters::table()[k].name);
    }
  }
};

// Reads a list of numbers and checks it against this build's values.
void expectNumbers(const Dictionary& d, const std::string& key, const double* expected, int count) {
  std::istringstream in(d.text(key));
  for (int k = 0; k < count; ++k) {
    double v;
    if (!(in >> v) || std::abs(v - expected[k]) > 1e-12 * std::max(1.0, std::abs(expected[k])))
      throw InputError(d.source(), d.line(key),
                       "<" + key + "> does not match this build's scaling (entry " + std::to_string(k + 1) +
                           "); the policy was trained with other ranges");
  }
}

void expectText(const Dictionary& d, const std::string& key, const std::string& expected) {
  if (d.text(key) != expected)
    throw InputError(d.source(), d.line(key), "<" + key + "> is '" + d.text(key) + "', this build expects '" +
                                                 expected + "'");
}

}  // namespace

void writePolicyFiles(const std::filesystem::path& xmlFile, const ActorCritic& learner,
                      const PolicyStateScaling& scaling, const PolicyProvenance& provenance) {
  if (const std::string problem = learner.nonFiniteWeightProblem(); !problem.empty())
    throw std::runtime_error(xmlFile.string() + ": not written: " + problem);
  std::filesystem::path actorFile = xmlFile;
  actorFile.replace_extension(".pt");
  learner.saveActor(actorFile);
  const NetworkLayout& layout = learner.layout();
  const PolicyDescription description(layout.actionSize);
  Dictionary d("policy");
  d.setComment(
      "passageMesh trained policy (docs/case-format.md). The actor maps the state, scaled to "
      "[-1, 1] from [stateLower, stateUpper] (linearly in the value, or in its logarithm where "
      "stateScale says log), to the action in [-1, 1], scaled linearly to the meshing parameters "
      "from [actionLower, actionUpper] (lengths in chords).");
  d.set("format", policyFormat);
  d.set("actor", actorFile.filename().string());
  d.set("hiddenLayers", layout.hiddenText());
  d.set("leakySlope", layout.leakySlope);
  d.set("layers", "layers.N.weight and layers.N.bias for N = 0, 2, 4, ...: Linear; odd N: LeakyReLU; "
                  "tanh on the output");
  d.set("stateNames", joinedWords(policyStateNames(), " "));
  d.set("stateLower", numbersText(scaling.lower));
  d.set("stateUpper", numbersText(scaling.upper));
  d.set("stateScale", scaleText(scaling));
  d.set("actionNames", joinedWords(description.actionNames, " "));
  d.set("actionLower", numbersText(description.actionLower));
  d.set("actionUpper", numbersText(description.actionUpper));
  d.set("trainedEpisodes", std::to_string(provenance.episodes));
  d.set("validationMeanReward", provenance.validationMeanReward);
  d.set("command", provenance.command);
  d.write(xmlFile);
}

struct Policy::Actor {
  NetworkLayout layout;
  PolicyStateScaling scaling;
  FullyConnected network{nullptr};
  PolicyProvenance provenance;
  std::filesystem::path file;  // the .pt

  static Actor load(const Dictionary& d, const std::filesystem::path& xmlFile);
};

struct Policy::Members {
  std::vector<Actor> actors;
  PolicyProvenance provenance;  // the single actor's, or the ensemble's
};

Policy::Policy() : members_(std::make_unique<Members>()) {}
Policy::~Policy() = default;
Policy::Policy(Policy&&) noexcept = default;
Policy& Policy::operator=(Policy&&) noexcept = default;

Policy Policy::load(const std::filesystem::path& xmlFile) {
  if (!std::filesystem::exists(xmlFile)) throw InputError(xmlFile.string(), 0, "no such policy file");
  const Dictionary d = Dictionary::read(xmlFile, "policy", policyOrEnsembleKeys());
  d.require({"format"});
  Policy policy;
  Members& m = *policy.members_;
  if (d.text("format") != ensembleFormat) {
    m.actors.push_back(Actor::load(d, xmlFile));
    m.provenance = m.actors.front().provenance;
    return policy;
  }
  for (const std::string& key : policyKeysOfFormat2())
    if (d.has(key) && key != "format" && key != "validationMeanReward" && key != "command")
      throw InputError(d.source(), d.line(key), "<" + key + "> belongs to a member's file, not to an ensemble's");
  d.require({"members"});
  std::istringstream names(d.text("members"));
  std::string firstMember;
  for (std::string name; names >> name;) {
    const std::filesystem::path memberFile = xmlFile.parent_path() / name;
    if (!std::filesystem::exists(memberFile))
      throw InputError(d.source(), d.line("members"), "the member " + memberFile.string() + " does not exist");
    const Dictionary member = Dictionary::read(memberFile, "policy", policyOrEnsembleKeys());
    member.require({"format"});
    if (member.text("format") == ensembleFormat)
      throw InputError(member.source(), member.line("format"), "a member must be a single policy, not an ensemble");
    m.actors.push_back(Actor::load(member, memberFile));
    const Actor& first = m.actors.front();
    const Actor& added = m.actors.back();
    if (firstMember.empty()) firstMember = name;
    if (added.scaling.logarithmic != first.scaling.logarithmic)
      throw InputError(member.source(), member.line(member.has("stateScale") ? "stateScale" : "format"),
                       "<stateScale> differs from the first member's (" + firstMember +
                           "): the members must scale the state alike");
    m.provenance.episodes += added.provenance.episodes;
  }
  if (m.actors.empty())
    throw InputError(d.source(), d.line("members"), "<members> expects one or more member policy files");
  if (d.has("validationMeanReward")) m.provenance.validationMeanReward = d.scalar("validationMeanReward");
  if (d.has("command")) m.provenance.command = d.text("command");
  return policy;
}

Policy::Actor Policy::Actor::load(const Dictionary& d, const std::filesystem::path& xmlFile) {
  if (d.has("members"))
    throw InputError(d.source(), d.line("members"), "<members> belongs to an ensemble's file (format '" +
                                                        std::string(ensembleFormat) + "')");
  d.require(policyKeys());
  const bool format1 = d.text("format") == policyFormat1;
  if (!format1) expectText(d, "format", policyFormat);
  // The action: every meshing parameter, or the method's eight (a policy trained before
  // the splits were parameters; its meshes have them at 0).
  const int actionSize = d.text("actionNames") == joinedWords(PolicyDescription(MeshingParameters::methodSize).actionNames, " ")
                             ? MeshingParameters::methodSize
                             : policyActionSize;
  const PolicyDescription description(actionSize);
  expectText(d, "stateNames", joinedWords(policyStateNames(), " "));
  Actor a;
  // This build's ranges; every value linear (format 1) until <stateScale> says otherwise.
  a.scaling = policyStateScaling(BladeParameterRange::readDefault(), EdgeRadiusScale::linear);
  if (!format1) {
    d.require({"stateScale"});
    std::istringstream scales(d.text("stateScale"));
    std::string word;
    for (int k = 0; k < policyStateSize; ++k) {
      if (!(scales >> word) || (word != "linear" && word != "log"))
        throw InputError(d.source(), d.line("stateScale"),
                         "<stateScale> expects " + std::to_string(policyStateSize) + " words, each 'linear' or 'log'");
      a.scaling.logarithmic[k] = word == "log";
    }
    if (scales >> word)
      throw InputError(d.source(), d.line("stateScale"),
                       "<stateScale> has more than " + std::to_string(policyStateSize) + " words");
    for (int k = 0; k < policyStateSize; ++k)
      if (a.scaling.logarithmic[k] && !(a.scaling.lower[k] > 0))
        throw InputError(d.source(), d.line("stateScale"), "<stateScale> says log for " + policyStateNames()[k] +
                                                               ", whose lower bound is not positive");
  }
  expectText(d, "actionNames", joinedWords(description.actionNames, " "));
  expectNumbers(d, "stateLower", a.scaling.lower.data(), policyStateSize);
  expectNumbers(d, "stateUpper", a.scaling.upper.data(), policyStateSize);
  expectNumbers(d, "actionLower", description.actionLower.data(), actionSize);
  expectNumbers(d, "actionUpper", description.actionUpper.data(), actionSize);

  a.layout.stateSize = policyStateSize;
  a.layout.actionSize = actionSize;
  a.layout.leakySlope = d.scalar("leakySlope");
  a.layout.hidden.clear();
  std::istringstream widths(d.text("hiddenLayers"));
  for (int w; widths >> w;) {
    if (w < 1) throw InputError(d.source(), d.line("hiddenLayers"), "<hiddenLayers> expects positive widths");
    a.layout.hidden.push_back(w);
  }
  if (a.layout.hidden.empty() || !widths.eof())
    throw InputError(d.source(), d.line("hiddenLayers"), "<hiddenLayers> expects layer widths, e.g. \"512 256 256 128\"");
  a.provenance.episodes = d.integer("trainedEpisodes");
  a.provenance.validationMeanReward = d.scalar("validationMeanReward");
  a.provenance.command = d.text("command");

  const std::filesystem::path actorFile = xmlFile.parent_path() / d.text("actor");
  if (!std::filesystem::exists(actorFile))
    throw InputError(d.source(), d.line("actor"), "the actor file " + actorFile.string() + " does not exist");
  a.network = makeActor(a.layout);
  a.file = actorFile;
  if (const std::string problem = zipChecksumProblem(actorFile); !problem.empty())
    throw InputError(actorFile.string(), 0, problem + " (expected the actor LibTorch wrote)");
  try {
    // LibTorch's load takes each tensor's shape from the file, so the shapes the layout
    // asks for are compared afterwards.
    std::vector<std::vector<long>> shapes;
    for (const auto& p : a.network->parameters()) shapes.push_back(p.sizes().vec());
    torch::serialize::InputArchive archive;
    archive.load_from(actorFile.string());
    a.network->load(archive);
    const auto loaded = a.network->parameters();
    bool same = loaded.size() == shapes.size();
    for (std::size_t k = 0; same && k < shapes.size(); ++k)
      same = loaded[k].sizes().vec() == shapes[k] && loaded[k].scalar_type() == torch::kFloat32;
    if (!same) throw std::runtime_error("its weight shapes or types differ");
  } catch (const std::exception& e) {
    std::string what = e.what();
    what = what.substr(0, what.find('\n'));
    throw InputError(actorFile.string(), 0, "not an actor of the layout " + xmlFile.filename().string() +
                                                " describes (" + what + ")");
  }
  if (const std::string problem = nonFiniteWeightProblem(a.network, "actor"); !problem.empty())
    throw InputError(actorFile.string(), 0, problem + " (a diverged run or a corrupt file)");
  a.network->eval();
  return a;
}

namespace {

// A member without the splits knows nothing of them: where no member has an action (a
// policy written before the splits), the method's outer loop.
const PolicyAction& actionWithoutSplits() {
  static const PolicyAction withoutSplits = policyAction(MeshingParameters{}, 1.0);
  return withoutSplits;
}

}  // namespace

std::vector<Policy::MemberAction> Policy::memberActions(const PolicyState& state) const {
  torch::NoGradGuard noGrad;
  PolicyBatch s(1, policyStateSize);
  for (int k = 0; k < policyStateSize; ++k) s(0, k) = state[k];
  const torch::Tensor input = tensorOf(s);
  std::vector<MemberAction> actions;
  std::vector<Actor>& actors = members_->actors;  // forward() is not const in LibTorch
  for (Actor& actor : actors) {
    const PolicyBatch a = batchOf(actor.network->forward(input));
    MemberAction member{actionWithoutSplits(), actor.layout.actionSize};
    for (int k = 0; k < actor.layout.actionSize; ++k) member.action[k] = a(0, k);
    actions.push_back(member);
  }
  return actions;
}

PolicyAction Policy::act(const PolicyState& state) const { return meanAction(memberActions(state)); }

PolicyAction Policy::meanAction(const std::vector<MemberAction>& memberActions) {
  PolicyAction action{};
  std::array<int, policyActionSize> members{};  // how many members give each action
  for (const MemberAction& member : memberActions) {
    for (int k = 0; k < member.size; ++k) {
      action[k] += member.action[k];
      ++members[k];
    }
  }
  // Each action is the mean over the members that have it: a member trained without the
  // splits does not pull them to 0 in a mixed ensemble. A single actor's action is exactly
  // as its network gives it (x / 1 == x).
  for (int k = 0; k < policyActionSize; ++k)
    action[k] = members[k] > 0 ? action[k] / members[k] : actionWithoutSplits()[k];
  return action;
}

std::vector<PolicyAction> Policy::actionsInTurn(const PolicyState& state) const {
  const std::vector<MemberAction> members = memberActions(state);  // one forward pass each
  std::vector<PolicyAction> actions{meanAction(members)};
  if (members.size() > 1)
    for (const MemberAction& member : members) actions.push_back(member.action);
  return actions;
}

PolicyState Policy::state(const BladeParameters& blade, const PassageCondition& condition) const {
  return policyState(blade, condition, members_->actors.front().scaling);
}

MeshingParameters Policy::meshingParameters(const BladeParameters& blade,
                                            const PassageCondition& condition) const {
  return meshingParametersOf(act(state(blade, condition)), blade.chord);
}

const PolicyStateScaling& Policy::stateScaling() const { return members_->actors.front().scaling; }
const std::filesystem::path& Policy::actorFile() const { return members_->actors.front().file; }

const NetworkLayout& Policy::layout() const { return members_->actors.front().layout; }
const PolicyProvenance& Policy::provenance() const { return members_->provenance; }
int Policy::memberCount() const { return static_cast<int>(members_->actors.size()); }

std::filesystem::path defaultPolicyFile() { return findEtcFile("policy/policy.xml"); }

}  // namespace passageMesh
