#include "passageMesh/policy/PolicyTrainOptions.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>

#include "passageMesh/core/Dictionary.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/JoinedWords.hpp"
#include "passageMesh/core/NumberFormat.hpp"
#include "passageMesh/passage/MeshingParameters.hpp"
#include "passageMesh/policy/PolicyScaling.hpp"

namespace passageMesh {

double PolicyTrainOptions::noiseSigma(long episode) const {
  if (episode < noiseStartEpisodes) return noiseStartSigma;
  return noiseAmplitude *
         (std::cos(2.0 * std::numbers::pi * static_cast<double>(episode) / static_cast<double>(noisePeriod)) + 1.0);
}

NetworkLayout PolicyTrainOptions::layout(int stateSize, int actionSize) const {
  NetworkLayout l;
  l.stateSize = stateSize;
  l.actionSize = actionSize;
  l.hidden = hidden;
  l.leakySlope = leakySlope;
  l.critic = criticModel;
  return l;
}

PassageEnvironment PolicyTrainOptions::passageEnvironment() const {
  return PassageEnvironment(edgeRadii,
                            policyStateScaling(BladeParameterRange::readDefault(),
                                               edgeRadii == EdgeRadiusDraw::halfLogUniform ? EdgeRadiusScale::logarithmic
                                                                                           : EdgeRadiusScale::linear),
                            trainingMeshes);
}

std::vector<double> PolicyTrainOptions::actorStartAction(const PolicyEnvironment& environment) const {
  switch (actorStart) {
    case ActorStart::random: return {};
    case ActorStart::defaults: return environment.defaultAction();
    case ActorStart::meshDict: {
      const PolicyAction a = policyAction(actorStartParameters, 1.0);
      return {a.begin(), a.end()};
    }
  }
  return {};
}

namespace {

// The words of one enumerated setting.
template <typename E>
struct Words {
  const char* setting;
  std::vector<std::pair<std::string, E>> words;

  E named(const std::string& word) const {
    for (const auto& [w, value] : words)
      if (w == word) return value;
    std::string list;
    for (std::size_t k = 0; k < words.size(); ++k)
      list += std::string(k == 0 ? "" : k + 1 == words.size() ? " or " : ", ") + "'" + words[k].first + "'";
    throw InputError("<" + std::string(setting) + "> is " + list + ", not '" + word + "'");
  }
  std::string nameOf(E value) const {
    for (const auto& [w, v] : words)
      if (v == value) return w;
    return "?";
  }
};

const Words<ActorStart> actorStartWords{"actorStart", {{"random", ActorStart::random}, {"defaults", ActorStart::defaults}, {"meshDict", ActorStart::meshDict}}};
const Words<EdgeRadiusDraw> edgeRadiusWords{
    "edgeRadii", {{"halfLogUniform", EdgeRadiusDraw::halfLogUniform}, {"uniform", EdgeRadiusDraw::uniform}}};
const Words<TrainingMeshes> trainingMeshesWords{
    "trainingMeshes", {{"asPolicyMesh", TrainingMeshes::asPolicyMesh}, {"asAsked", TrainingMeshes::asAsked}}};
const Words<LearnerSchedule> learnerScheduleWords{
    "learnerSchedule",
    {{"afterRollouts", LearnerSchedule::afterRollouts}, {"duringNextRollouts", LearnerSchedule::duringNextRollouts}}};
const Words<CriticModel> criticModelWords{
    "criticModel",
    {{"reward", CriticModel::reward},
     {"validityAndQuality", CriticModel::validityAndQuality},
     {"validityAndBoundedQuality", CriticModel::validityAndBoundedQuality}}};

}  // namespace

ActorStart actorStartNamed(const std::string& word) { return actorStartWords.named(word); }
EdgeRadiusDraw edgeRadiusDrawNamed(const std::string& word) { return edgeRadiusWords.named(word); }
CriticModel criticModelNamed(const std::string& word) { return criticModelWords.named(word); }
TrainingMeshes trainingMeshesNamed(const std::string& word) { return trainingMeshesWords.named(word); }
LearnerSchedule learnerScheduleNamed(const std::string& word) { return learnerScheduleWords.named(word); }
std::string nameOf(ActorStart value) { return actorStartWords.nameOf(value); }
std::string nameOf(EdgeRadiusDraw value) { return edgeRadiusWords.nameOf(value); }
std::string nameOf(CriticModel value) { return criticModelWords.nameOf(value); }
std::string nameOf(TrainingMeshes value) { return trainingMeshesWords.nameOf(value); }
std::string nameOf(LearnerSchedule value) { return learnerScheduleWords.nameOf(value); }

namespace {

// One row per key: how it is read and written, and the smallest value allowed.
struct Key {
  const char* name;
  std::function<void(const Dictionary&, PolicyTrainOptions&)> read;
  std::function<std::string(const PolicyTrainOptions&)> write;
};

template <typename T>
std::function<void(const Dictionary&, PolicyTrainOptions&)> readInteger(const char* name, T PolicyTrainOptions::*member,
                                                                        long minimum) {
  return [=](const Dictionary& d, PolicyTrainOptions& o) {
    const long v = d.integer(name);
    // int members stay below 2^31 (a larger value would wrap); long ones are bounded by the reader.
    const long maximum = sizeof(T) < sizeof(long) ? static_cast<long>(std::numeric_limits<int>::max())
                                                  : std::numeric_limits<long>::max();
    if (v < minimum || v > maximum)
      throw InputError(d.source(), d.line(name), "<" + std::string(name) + "> must be in [" +
                                                     std::to_string(minimum) + ", " + std::to_string(maximum) +
                                                     "], not " + std::to_string(v));
    o.*member = static_cast<T>(v);
  };
}

std::function<void(const Dictionary&, PolicyTrainOptions&)> readPositive(const char* name,
                                                                         double& (*field)(PolicyTrainOptions&),
                                                                         bool zeroAllowed) {
  return [=](const Dictionary& d, PolicyTrainOptions& o) {
    const double v = d.scalar(name);
    if (!std::isfinite(v) || v < 0 || (v == 0 && !zeroAllowed))
      throw InputError(d.source(), d.line(name), "<" + std::string(name) + "> must be " +
                                                     (zeroAllowed ? "at least 0" : "positive"));
    field(o) = v;
  };
}

// A word of an enumerated setting, e.g. <actorStart> random or defaults.
template <typename E>
std::function<void(const Dictionary&, PolicyTrainOptions&)> readChoice(const Words<E>& words,
                                                                       E PolicyTrainOptions::*member) {
  return [&words, member](const Dictionary& d, PolicyTrainOptions& o) {
    try {
      o.*member = words.named(d.text(words.setting));
    } catch (const InputError& e) {
      throw InputError(d.source(), d.line(words.setting), e.what());
    }
  };
}

// Meshing-parameter names (the action's entries), e.g. "splitIn splitOut", as indices into
// the action; an unknown or repeated name is an InputError listing the known ones.
std::function<void(const Dictionary&, PolicyTrainOptions&)> readActionNames(const char* name,
                                                                           std::vector<int> PolicyTrainOptions::*member) {
  return [=](const Dictionary& d, PolicyTrainOptions& o) {
    const auto& names = MeshingParameters::names();
    std::istringstream in(d.text(name));
    std::vector<int> indices;
    for (std::string word; in >> word;) {
      const auto found = std::find(names.begin(), names.end(), word);
      const int index = static_cast<int>(found - names.begin());
      if (found == names.end() || std::find(indices.begin(), indices.end(), index) != indices.end()) {
        throw InputError(d.source(), d.line(name), "<" + std::string(name) + "> names meshing parameters, each once (" +
                                                       joinedWords(names, " ") + "); got '" + word + "'");
      }
      indices.push_back(index);
    }
    o.*member = indices;
  };
}

std::string actionNamesText(const std::vector<int>& indices) {
  std::vector<std::string> words;
  for (int k : indices) words.push_back(MeshingParameters::names()[static_cast<std::size_t>(k)]);
  return joinedWords(words, " ");
}

const std::vector<Key>& keys() {
  using O = PolicyTrainOptions;
  static const std::vector<Key> k{
      {"episodes", readInteger("episodes", &O::episodes, 1), [](const O& o) { return std::to_string(o.episodes); }},
      {"batchEpisodes", readInteger("batchEpisodes", &O::batchEpisodes, 1), [](const O& o) { return std::to_string(o.batchEpisodes); }},
      {"minibatch", readInteger("minibatch", &O::minibatch, 1), [](const O& o) { return std::to_string(o.minibatch); }},
      {"actorLearningRate", readPositive("actorLearningRate", [](O& o) -> double& { return o.learningRates.actor; }, false),
       [](const O& o) { return formatExact(o.learningRates.actor); }},
      {"criticLearningRate", readPositive("criticLearningRate", [](O& o) -> double& { return o.learningRates.critic; }, false),
       [](const O& o) { return formatExact(o.learningRates.critic); }},
      {"hiddenLayers",
       [](const Dictionary& d, O& o) {
         std::istringstream in(d.text("hiddenLayers"));
         std::vector<int> widths;
         std::string word;
         while (in >> word) {
           std::size_t used = 0;
           int w = 0;
           try { w = std::stoi(word, &used); } catch (const std::exception&) { used = 0; }
           if (used != word.size() || w < 1)
             throw InputError(d.source(), d.line("hiddenLayers"),
                              "<hiddenLayers> expects positive layer widths, e.g. \"512 256 256 128\"; got '" + word + "'");
           widths.push_back(w);
         }
         if (widths.empty())
           throw InputError(d.source(), d.line("hiddenLayers"), "<hiddenLayers> needs at least one layer width");
         o.hidden = widths;
       },
       [](const O& o) { return NetworkLayout{0, 0, o.hidden, o.leakySlope}.hiddenText(); }},
      {"leakySlope", readPositive("leakySlope", [](O& o) -> double& { return o.leakySlope; }, true),
       [](const O& o) { return formatExact(o.leakySlope); }},
      {"criticUpdatesPerEpisode", readInteger("criticUpdatesPerEpisode", &O::criticUpdatesPerEpisode, 1),
       [](const O& o) { return std::to_string(o.criticUpdatesPerEpisode); }},
      {"actorUpdateEvery", readInteger("actorUpdateEvery", &O::actorUpdateEvery, 1), [](const O& o) { return std::to_string(o.actorUpdateEvery); }},
      {"actorUpdatesFrom", readInteger("actorUpdatesFrom", &O::actorUpdatesFrom, 0), [](const O& o) { return std::to_string(o.actorUpdatesFrom); }},
      {"actorTrainsOnly", readActionNames("actorTrainsOnly", &O::actorTrainedActions),
       [](const O& o) { return actionNamesText(o.actorTrainedActions); }},
      {"heldActions", readActionNames("heldActions", &O::heldActions),
       [](const O& o) { return actionNamesText(o.heldActions); }},
      {"actionBoundPenalty", readPositive("actionBoundPenalty", [](O& o) -> double& { return o.actionBoundPenalty; }, true),
       [](const O& o) { return formatExact(o.actionBoundPenalty); }},
      {"restoreBelowValidShare",
       readPositive("restoreBelowValidShare", [](O& o) -> double& { return o.restoreBelowValidShare; }, true),
       [](const O& o) { return formatExact(o.restoreBelowValidShare); }},
      {"actorAverageDecay", readPositive("actorAverageDecay", [](O& o) -> double& { return o.actorAverageDecay; }, true),
       [](const O& o) { return formatExact(o.actorAverageDecay); }},
      {"noiseStartSigma", readPositive("noiseStartSigma", [](O& o) -> double& { return o.noiseStartSigma; }, true),
       [](const O& o) { return formatExact(o.noiseStartSigma); }},
      {"noiseStartEpisodes", readInteger("noiseStartEpisodes", &O::noiseStartEpisodes, 0), [](const O& o) { return std::to_string(o.noiseStartEpisodes); }},
      {"noiseAmplitude", readPositive("noiseAmplitude", [](O& o) -> double& { return o.noiseAmplitude; }, true),
       [](const O& o) { return formatExact(o.noiseAmplitude); }},
      {"noisePeriod", readInteger("noisePeriod", &O::noisePeriod, 1), [](const O& o) { return std::to_string(o.noisePeriod); }},
      {"wideNoiseShare", readPositive("wideNoiseShare", [](O& o) -> double& { return o.wideNoiseShare; }, true),
       [](const O& o) { return formatExact(o.wideNoiseShare); }},
      {"wideNoiseSigma", readPositive("wideNoiseSigma", [](O& o) -> double& { return o.wideNoiseSigma; }, false),
       [](const O& o) { return formatExact(o.wideNoiseSigma); }},
      {"wideNoiseActions", readActionNames("wideNoiseActions", &O::wideNoiseActions),
       [](const O& o) { return actionNamesText(o.wideNoiseActions); }},
      {"bufferCapacity", readInteger("bufferCapacity", &O::bufferCapacity, 1), [](const O& o) { return std::to_string(o.bufferCapacity); }},
      {"validationEvery", readInteger("validationEvery", &O::validationEvery, 1), [](const O& o) { return std::to_string(o.validationEvery); }},
      {"validationPassages", readInteger("validationPassages", &O::validationPassages, 1), [](const O& o) { return std::to_string(o.validationPassages); }},
      {"validationSeed", readInteger("validationSeed", &O::validationSeed, 0), [](const O& o) { return std::to_string(o.validationSeed); }},
      {"checkpointEvery", readInteger("checkpointEvery", &O::checkpointEvery, 1), [](const O& o) { return std::to_string(o.checkpointEvery); }},
      {"logEvery", readInteger("logEvery", &O::logEvery, 1), [](const O& o) { return std::to_string(o.logEvery); }},
      {"actorStart", readChoice(actorStartWords, &O::actorStart), [](const O& o) { return nameOf(o.actorStart); }},
      {"actorStartMeshDict", [](const Dictionary& d, O& o) { o.actorStartMeshDict = d.text("actorStartMeshDict"); },
       [](const O& o) { return o.actorStartMeshDict.string(); }},
      {"edgeRadii", readChoice(edgeRadiusWords, &O::edgeRadii), [](const O& o) { return nameOf(o.edgeRadii); }},
      {"trainingMeshes", readChoice(trainingMeshesWords, &O::trainingMeshes),
       [](const O& o) { return nameOf(o.trainingMeshes); }},
      {"learnerSchedule", readChoice(learnerScheduleWords, &O::learnerSchedule),
       [](const O& o) { return nameOf(o.learnerSchedule); }},
      {"criticModel", readChoice(criticModelWords, &O::criticModel), [](const O& o) { return nameOf(o.criticModel); }},
      {"validityBarrier", readPositive("validityBarrier", [](O& o) -> double& { return o.validityBarrier; }, true),
       [](const O& o) { return formatExact(o.validityBarrier); }},
      {"searchEvery", readInteger("searchEvery", &O::searchEvery, 0), [](const O& o) { return std::to_string(o.searchEvery); }},
      {"searchBudget", readInteger("searchBudget", &O::searchBudget, 2), [](const O& o) { return std::to_string(o.searchBudget); }},
      {"imitationWeight", readPositive("imitationWeight", [](O& o) -> double& { return o.imitationWeight; }, true),
       [](const O& o) { return formatExact(o.imitationWeight); }},
      {"seed", readInteger("seed", &O::seed, 0), [](const O& o) { return std::to_string(o.seed); }},
      {"threads", readInteger("threads", &O::threads, 0), [](const O& o) { return std::to_string(o.threads); }},
  };
  return k;
}

// "name value ..." of meshing parameters, exact.
std::string meshDictText(const MeshingParameters& p) {
  std::string text;
  const auto v = p.toArray();
  for (int k = 0; k < MeshingParameters::size; ++k)
    text += (k ? " " : "") + MeshingParameters::names()[k] + " " + formatExact(v[k]);
  return text;
}

// With <actorStart>meshDict: the parameters of <actorStartMeshDict> (relative to the case
// directory, the folder above system/), refused when outside the range box (a start the
// actor's tanh cannot reach).
void readActorStartMeshDict(const std::filesystem::path& file, const Dictionary& dict, PolicyTrainOptions& options) {
  const bool named = !options.actorStartMeshDict.empty();
  if (options.actorStart != ActorStart::meshDict) {
    if (named)
      throw InputError(file.string(), dict.line("actorStartMeshDict"),
                       "<actorStartMeshDict> is read only with <actorStart>meshDict</actorStart>");
    return;
  }
  if (!named)
    throw InputError(file.string(), dict.line("actorStart"),
                     "<actorStart>meshDict</actorStart> needs <actorStartMeshDict>, the meshDict file to start from");
  std::filesystem::path start = options.actorStartMeshDict;
  if (start.is_relative()) start = file.parent_path().parent_path() / start;
  if (!std::filesystem::is_regular_file(start))
    throw InputError(file.string(), dict.line("actorStartMeshDict"),
                     "<actorStartMeshDict> " + start.string() + " not found (paths are relative to the case directory)");
  std::vector<std::string> outside;
  options.actorStartParameters = readMeshDict(start, 1.0, &outside);
  if (!outside.empty())  // the reader's warning, without the clipping it would do for a mesh
    throw InputError(file.string(), dict.line("actorStartMeshDict"),
                     "the actor's start " + outside.front().substr(0, outside.front().rfind(", clipped")) +
                         ": the start must lie in the range box");
}

std::vector<std::string> keyNames() {
  std::vector<std::string> names;
  for (const Key& k : keys()) names.emplace_back(k.name);
  return names;
}

}  // namespace

PolicyTrainOptions readPolicyTrainDict(const std::filesystem::path& file) {
  PolicyTrainOptions options;
  if (!std::filesystem::exists(file)) return options;
  const Dictionary dict = Dictionary::read(file, "policyTrainDict", keyNames());
  for (const Key& k : keys())
    if (dict.has(k.name)) k.read(dict, options);
  if (options.validityBarrier > 0 && !hasValidity(options.criticModel))
    throw InputError(file.string(), dict.line("validityBarrier"),
                     "<validityBarrier> needs <criticModel>validityAndQuality</criticModel> (or "
                     "validityAndBoundedQuality): the '" +
                         nameOf(options.criticModel) + "' critic has no validity to put a barrier on");
  if (options.imitationWeight > 0 && options.searchEvery == 0)
    throw InputError(file.string(), dict.line("imitationWeight"),
                     "<imitationWeight> needs <searchEvery> above 0: without searches there are no "
                     "demonstrations to imitate");
  if (!options.heldActions.empty() && !options.actorTrainedActions.empty())
    throw InputError(file.string(), dict.line("heldActions"),
                     "<heldActions> and <actorTrainsOnly>: give one (<actorTrainsOnly> already holds every "
                     "action it does not name)");
  if (options.learnerSchedule == LearnerSchedule::duringNextRollouts && options.searchEvery > 0)
    throw InputError(file.string(), dict.line("learnerSchedule"),
                     "<learnerSchedule>duringNextRollouts</learnerSchedule> needs <searchEvery> 0: a search "
                     "uses the rollouts and the actor between two batches");
  if (options.restoreBelowValidShare > 1)
    throw InputError(file.string(), dict.line("restoreBelowValidShare"),
                     "<restoreBelowValidShare> is a share of the best validation's valid meshes: expected a value in "
                     "[0, 1], got " + formatExact(options.restoreBelowValidShare));
  if (options.actorAverageDecay >= 1)
    throw InputError(file.string(), dict.line("actorAverageDecay"),
                     "<actorAverageDecay> is the share of the averaged actor kept at each actor step: expected a "
                     "value in [0, 1), got " + formatExact(options.actorAverageDecay));
  if (options.wideNoiseShare > 1)
    throw InputError(file.string(), dict.line("wideNoiseShare"),
                     "<wideNoiseShare> is a share of the episodes: expected a value in [0, 1], got " +
                         formatExact(options.wideNoiseShare));
  readActorStartMeshDict(file, dict, options);
  if (options.minibatch > options.bufferCapacity)
    throw InputError(file.string(), dict.line(dict.has("minibatch") ? "minibatch" : "bufferCapacity"),
                     "<minibatch> " + std::to_string(options.minibatch) + " is larger than <bufferCapacity> " +
                         std::to_string(options.bufferCapacity) + ": the learner would never start");
  return options;
}

std::vector<std::pair<std::string, std::string>> trajectorySettings(const PolicyTrainOptions& options) {
  std::vector<std::pair<std::string, std::string>> settings;
  for (const Key& k : keys()) {
    const std::string name = k.name;
    if (name == "actorStartMeshDict")  // what decides the weights is the file's content, not its name
      settings.emplace_back("actorStartParameters", options.actorStart == ActorStart::meshDict
                                                        ? meshDictText(options.actorStartParameters)
                                                        : std::string());
    else if (name != "episodes" && name != "threads" && name != "checkpointEvery" && name != "logEvery")
      settings.emplace_back(name, k.write(options));
  }
  return settings;
}

std::string policyTrainDictXml(const PolicyTrainOptions& options) {
  Dictionary dict("policyTrainDict");
  dict.setComment("passageMesh policyTrain settings; see docs/case-format.md and docs/policy.md.");
  for (const Key& k : keys()) dict.set(k.name, k.write(options));
  return dict.toXml();
}

}  // namespace passageMesh
