#include "passageMesh/policy/PolicyTrainOptions.hpp"

#include <gtest/gtest.h>

#include "../TestFiles.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/policy/PolicyScaling.hpp"

using namespace passageMesh;

TEST(PolicyTrainOptions, TheWrittenDictionaryReadsBackToTheSameOptions) {
  PolicyTrainOptions o;
  o.episodes = 1234;
  o.hidden = {32, 16};
  o.learningRates = {3e-4, 1e-3};
  o.noiseAmplitude = 0.125;
  o.seed = 77;
  o.criticModel = CriticModel::validityAndQuality;
  o.validityBarrier = 0.125;
  o.searchEvery = 640;
  o.searchBudget = 96;
  o.imitationWeight = 0.25;
  o.wideNoiseShare = 0.1;
  o.wideNoiseSigma = 0.4;
  o.restoreBelowValidShare = 0.25;
  o.actorAverageDecay = 0.999;
  o.actorUpdatesFrom = 8000;
  o.actorTrainedActions = {9, 8};
  o.wideNoiseActions = {5};
  o.trainingMeshes = TrainingMeshes::asAsked;
  const auto file = testData::writeTempFile("policyTrainDict", "dict.xml", policyTrainDictXml(o));
  const PolicyTrainOptions back = readPolicyTrainDict(file);
  EXPECT_EQ(policyTrainDictXml(back), policyTrainDictXml(o));
  EXPECT_EQ(back.hidden, (std::vector<int>{32, 16}));
  EXPECT_EQ(back.learningRates.actor, 3e-4);
  EXPECT_EQ(back.criticModel, CriticModel::validityAndQuality);
  EXPECT_EQ(back.validityBarrier, 0.125);
  EXPECT_EQ(back.searchEvery, 640);
  EXPECT_EQ(back.searchBudget, 96);
  EXPECT_EQ(back.imitationWeight, 0.25);
  EXPECT_EQ(back.wideNoiseShare, 0.1);
  EXPECT_EQ(back.restoreBelowValidShare, 0.25);
  EXPECT_EQ(back.actorAverageDecay, 0.999);
  EXPECT_EQ(back.wideNoiseSigma, 0.4);
  EXPECT_EQ(back.actorUpdatesFrom, 8000);
  EXPECT_EQ(back.actorTrainedActions, (std::vector<int>{9, 8}));
  EXPECT_EQ(back.wideNoiseActions, (std::vector<int>{5}));
  EXPECT_EQ(back.trainingMeshes, TrainingMeshes::asAsked);
  EXPECT_NE(policyTrainDictXml(o).find("<actorTrainsOnly>splitOut splitIn</actorTrainsOnly>"), std::string::npos);
  EXPECT_EQ(readPolicyTrainDict(file.parent_path() / "missing.xml").episodes, PolicyTrainOptions{}.episodes);

  PolicyTrainOptions learnsDuringRollouts;  // (not with searches: above)
  learnsDuringRollouts.learnerSchedule = LearnerSchedule::duringNextRollouts;
  const auto scheduleFile =
      testData::writeTempFile("policyTrainDict", "schedule.xml", policyTrainDictXml(learnsDuringRollouts));
  EXPECT_EQ(readPolicyTrainDict(scheduleFile).learnerSchedule, LearnerSchedule::duringNextRollouts);
  PolicyTrainOptions held;  // (not with actorTrainsOnly: above)
  held.heldActions = {8, 9};
  const auto heldFile = testData::writeTempFile("policyTrainDict", "held.xml", policyTrainDictXml(held));
  EXPECT_EQ(readPolicyTrainDict(heldFile).heldActions, (std::vector<int>{8, 9}));
  EXPECT_NE(policyTrainDictXml(held).find("<heldActions>splitIn splitOut</heldActions>"), std::string::npos);
  EXPECT_EQ(PolicyTrainOptions{}.learnerSchedule, LearnerSchedule::afterRollouts);  // the paper's order
}

TEST(PolicyTrainOptions, PaperNoiseSchedule) {
  const PolicyTrainOptions o;
  EXPECT_EQ(o.noiseSigma(0), 1.0);
  EXPECT_EQ(o.noiseSigma(999), 1.0);
  EXPECT_NEAR(o.noiseSigma(1000), 0.5, 1e-15);
  EXPECT_NEAR(o.noiseSigma(1500), 0.0, 1e-15);
  EXPECT_NEAR(o.noiseSigma(1250), 0.25, 1e-12);
}

TEST(PolicyTrainOptions, BadValuesNameTheFileAndLine) {
  const auto bad = [](const std::string& body) {
    const auto file = testData::writeTempFile("policyTrainDict", "bad.xml",
                                              "<policyTrainDict>\n" + body + "\n</policyTrainDict>\n");
    try {
      readPolicyTrainDict(file);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(bad("<episodes>0</episodes>").find("bad.xml:2"), std::string::npos);
  EXPECT_NE(bad("<hiddenLayers>512 x</hiddenLayers>").find("hiddenLayers"), std::string::npos);
  EXPECT_NE(bad("<actorLearningRate>-1</actorLearningRate>").find("positive"), std::string::npos);
  EXPECT_NE(bad("<criticModel>quality</criticModel>").find("<criticModel> is 'reward', 'validityAndQuality' or 'validityAndBoundedQuality', not 'quality'"),
            std::string::npos);
  EXPECT_NE(bad("<validityBarrier>-0.1</validityBarrier>").find("at least 0"), std::string::npos);
  // A barrier on a critic without a validity network would be silently ignored.
  EXPECT_NE(bad("<criticModel>reward</criticModel>\n<validityBarrier>0.1</validityBarrier>")
                .find("bad.xml:3: <validityBarrier> needs <criticModel>validityAndQuality"),
            std::string::npos);
  EXPECT_NE(bad("<validityBarrier>0.1</validityBarrier>").find("needs <criticModel>"), std::string::npos);
  EXPECT_EQ(bad("<validityBarrier>0</validityBarrier>"), "accepted");
  EXPECT_NE(bad("<imitationWeight>1</imitationWeight>").find("bad.xml:2: <imitationWeight> needs <searchEvery> above 0"),
            std::string::npos) << bad("<imitationWeight>1</imitationWeight>");
  EXPECT_EQ(bad("<searchEvery>64</searchEvery>\n<imitationWeight>1</imitationWeight>"), "accepted");
  EXPECT_NE(bad("<searchEvery>64</searchEvery>\n<learnerSchedule>duringNextRollouts</learnerSchedule>")
                .find("bad.xml:3: <learnerSchedule>duringNextRollouts</learnerSchedule> needs <searchEvery> 0"),
            std::string::npos);
  EXPECT_NE(bad("<actorTrainsOnly>splitIn</actorTrainsOnly>\n<heldActions>splitOut</heldActions>")
                .find("bad.xml:3: <heldActions> and <actorTrainsOnly>: give one"),
            std::string::npos);
  EXPECT_NE(bad("<heldActions>splitIn splitUp</heldActions>").find("bad.xml:2: <heldActions> names meshing parameters"),
            std::string::npos);
  EXPECT_NE(bad("<learnerSchedule>overlapped</learnerSchedule>")
                .find("<learnerSchedule> is 'afterRollouts' or 'duringNextRollouts', not 'overlapped'"),
            std::string::npos);
  EXPECT_NE(bad("<searchBudget>1</searchBudget>").find("must be in [2,"), std::string::npos);
  EXPECT_NE(bad("<wideNoiseShare>1.5</wideNoiseShare>").find("bad.xml:2: <wideNoiseShare> is a share of the episodes"),
            std::string::npos) << bad("<wideNoiseShare>1.5</wideNoiseShare>");
  EXPECT_NE(bad("<restoreBelowValidShare>2</restoreBelowValidShare>")
                .find("bad.xml:2: <restoreBelowValidShare> is a share of the best validation's valid meshes"),
            std::string::npos) << bad("<restoreBelowValidShare>2</restoreBelowValidShare>");
  EXPECT_NE(bad("<actorAverageDecay>1</actorAverageDecay>")
                .find("bad.xml:2: <actorAverageDecay> is the share of the averaged actor kept at each actor step"),
            std::string::npos) << bad("<actorAverageDecay>1</actorAverageDecay>");
  EXPECT_NE(bad("<wideNoiseSigma>0</wideNoiseSigma>").find("bad.xml:2:"), std::string::npos);
  EXPECT_NE(bad("<actorTrainsOnly>splitIn splitUp</actorTrainsOnly>")
                .find("bad.xml:2: <actorTrainsOnly> names meshing parameters, each once (yIn yOut alphaCamber"),
            std::string::npos) << bad("<actorTrainsOnly>splitIn splitUp</actorTrainsOnly>");
  EXPECT_NE(bad("<actorTrainsOnly>nT nT</actorTrainsOnly>").find("got 'nT'"), std::string::npos);
  EXPECT_EQ(bad("<actorTrainsOnly></actorTrainsOnly>"), "accepted");
  EXPECT_NE(bad("<epsiodes>10</epsiodes>").find("epsiodes"), std::string::npos);
  EXPECT_NE(bad("<batchEpisodes>3000000000</batchEpisodes>").find("must be in [1, 2147483647]"), std::string::npos);
  EXPECT_NE(bad("<minibatch>200</minibatch><bufferCapacity>100</bufferCapacity>").find("never start"),
            std::string::npos);
  // No validation passages: no best validation, so no policy/policy.xml to ship.
  EXPECT_NE(bad("<validationPassages>0</validationPassages>").find("bad.xml:2: <validationPassages>"),
            std::string::npos) << bad("<validationPassages>0</validationPassages>");
}

TEST(PolicyTrainOptions, EveryEnumeratedSettingReadsBackFromItsWord) {
  for (const CriticModel v :
       {CriticModel::reward, CriticModel::validityAndQuality, CriticModel::validityAndBoundedQuality})
    EXPECT_EQ(criticModelNamed(nameOf(v)), v);
  for (const EdgeRadiusDraw v : {EdgeRadiusDraw::uniform, EdgeRadiusDraw::halfLogUniform})
    EXPECT_EQ(edgeRadiusDrawNamed(nameOf(v)), v);
  for (const ActorStart v : {ActorStart::random, ActorStart::defaults, ActorStart::meshDict}) EXPECT_EQ(actorStartNamed(nameOf(v)), v);
  for (const TrainingMeshes v : {TrainingMeshes::asPolicyMesh, TrainingMeshes::asAsked})
    EXPECT_EQ(trainingMeshesNamed(nameOf(v)), v);
  for (const LearnerSchedule v : {LearnerSchedule::afterRollouts, LearnerSchedule::duringNextRollouts})
    EXPECT_EQ(learnerScheduleNamed(nameOf(v)), v);
  EXPECT_EQ(nameOf(CriticModel::validityAndQuality), "validityAndQuality");
  try {
    edgeRadiusDrawNamed("Uniform");  // words are case-sensitive, as in the dictionary
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "<edgeRadii> is 'halfLogUniform' or 'uniform', not 'Uniform'");
  }
}

namespace {

// A case folder with system/policyTrainDict.xml (body inside <policyTrainDict>) and
// system/start.xml (body inside <meshDict>); the dictionary's path.
std::filesystem::path startCase(const std::string& name, const std::string& trainBody, const std::string& startBody) {
  testData::writeTempFile(name + "/system", "start.xml", "<meshDict>\n" + startBody + "\n</meshDict>\n");
  return testData::writeTempFile(name + "/system", "policyTrainDict.xml",
                                 "<policyTrainDict>\n" + trainBody + "\n</policyTrainDict>\n");
}

std::string readError(const std::filesystem::path& file) {
  try {
    readPolicyTrainDict(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

const std::string startFromFile = "<actorStart>meshDict</actorStart>\n<actorStartMeshDict>system/start.xml</actorStartMeshDict>";

}  // namespace

TEST(PolicyTrainOptions, TheActorStartsAtTheMeshDictItNamesRelativeToTheCase) {
  const auto file = startCase("startCase", startFromFile, "<yOut>-0.01c</yOut>\n<betaIn>0.492</betaIn>\n<nT>372</nT>");
  const PolicyTrainOptions o = readPolicyTrainDict(file);
  ASSERT_EQ(o.actorStart, ActorStart::meshDict);
  EXPECT_EQ(o.actorStartMeshDict, "system/start.xml");
  // Lengths in chords (the start is chord-normalised); keys the file lacks take the defaults.
  MeshingParameters expected = MeshingParameters::defaults(1.0);
  expected.yOut = -0.01;
  expected.betaIn = 0.492;
  expected.nT = 372;
  EXPECT_EQ(o.actorStartParameters.toArray(), expected.toArray());
  const PolicyAction a = policyAction(expected, 1.0);
  EXPECT_EQ(o.actorStartAction(o.passageEnvironment()), std::vector<double>(a.begin(), a.end()));
  EXPECT_NE(o.actorStartAction(o.passageEnvironment()), PolicyTrainOptions{}.actorStartAction(o.passageEnvironment()));
  PolicyTrainOptions random;
  random.actorStart = ActorStart::random;
  EXPECT_TRUE(random.actorStartAction(random.passageEnvironment()).empty());
  // A resumed run is checked against the file's content, not its name.
  const auto settingOf = [](const PolicyTrainOptions& options) {
    for (const auto& [key, value] : trajectorySettings(options))
      if (key == "actorStartParameters") return value;
    return std::string("missing");
  };
  EXPECT_NE(settingOf(o).find("betaIn 0.49199999999999999"), std::string::npos) << settingOf(o);
  EXPECT_EQ(settingOf(PolicyTrainOptions{}), "");
  PolicyTrainOptions moved = o;
  moved.actorStartMeshDict = "elsewhere.xml";
  EXPECT_EQ(settingOf(moved), settingOf(o));
  moved.actorStartParameters.betaIn = 0.5;
  EXPECT_NE(settingOf(moved), settingOf(o));
}

TEST(PolicyTrainOptions, AnActorStartFileThatCannotBeUsedIsRefusedWithTheLine) {
  EXPECT_NE(readError(startCase("startMissingKey", "<actorStart>meshDict</actorStart>", ""))
                .find("policyTrainDict.xml:2: <actorStart>meshDict</actorStart> needs <actorStartMeshDict>"),
            std::string::npos);
  EXPECT_NE(readError(startCase("startUnused", "<actorStartMeshDict>system/start.xml</actorStartMeshDict>", ""))
                .find("policyTrainDict.xml:2: <actorStartMeshDict> is read only with <actorStart>meshDict"),
            std::string::npos);
  EXPECT_NE(readError(startCase("startNoFile",
                                "<actorStart>meshDict</actorStart>\n<actorStartMeshDict>system/none.xml</actorStartMeshDict>", ""))
                .find("policyTrainDict.xml:3: <actorStartMeshDict> "),
            std::string::npos);
  const std::string outside = readError(startCase("startOutside", startFromFile, "<betaIn>0.95</betaIn>"));
  EXPECT_NE(outside.find("policyTrainDict.xml:3: the actor's start "), std::string::npos) << outside;
  EXPECT_NE(outside.find("start.xml: <betaIn> 0.94999999999999996 is outside [0.1, 0.9]: "
                         "the start must lie in the range box"),
            std::string::npos)
      << outside;
  EXPECT_NE(readError(startCase("startBadValue", startFromFile, "<nT>many</nT>")).find("start.xml:2"), std::string::npos);
}

TEST(PolicyTrainOptions, TheShippedTrainingDictionaryReadsAndStartsAtItsStartFile) {
  const std::filesystem::path tutorial = std::filesystem::path(PASSAGEMESH_SOURCE_DIR) / "tutorials" / "policyTrain";
  const PolicyTrainOptions o = readPolicyTrainDict(tutorial / "system" / "policyTrainDict.xml");
  ASSERT_EQ(o.actorStart, ActorStart::meshDict);
  EXPECT_EQ(o.actorStartParameters.toArray(),
            readMeshDict(tutorial / "system" / "actorStartMeshDict.xml", 1.0).toArray());
  EXPECT_NE(o.actorStartParameters.toArray(), MeshingParameters::defaults(1.0).toArray());
}

// The shipped ensemble's members are the two-stage tutorial's recipe with seeds 1, 2 and 3
// (docs/policy.md "The shipped policy", tutorials/policyTrainEnsemble): the dictionaries
// beside each must say exactly that, or the recorded command would not reproduce it.
TEST(PolicyTrainOptions, TheShippedMembersDictionariesAreTheTwoStageRecipeWithTheirSeeds) {
  const std::filesystem::path source(PASSAGEMESH_SOURCE_DIR);
  const std::filesystem::path recipe = source / "tutorials" / "policyTrainTwoStage";
  const std::vector<std::pair<std::string, std::string>> stages{
      {"policyTrainDict-stage1.xml", "stage1"}, {"policyTrainDict-A.xml", "stage2A"}, {"policyTrainDict-B.xml", "stage2B"}};
  for (const unsigned seed : {1u, 2u, 3u}) {
    const std::filesystem::path member = source / "etc" / "policy" / ("seed" + std::to_string(seed) + "critic2");
    for (const auto& [memberDict, recipeFolder] : stages) {
      SCOPED_TRACE(member.filename().string() + "/" + memberDict);
      // (the reader gives the defaults for a missing file: both must exist)
      const std::filesystem::path recipeDict = recipe / recipeFolder / "system" / "policyTrainDict.xml";
      ASSERT_TRUE(std::filesystem::exists(member / memberDict));
      ASSERT_TRUE(std::filesystem::exists(recipeDict));
      const PolicyTrainOptions shipped = readPolicyTrainDict(member / memberDict);
      PolicyTrainOptions expected = readPolicyTrainDict(recipeDict);
      EXPECT_EQ(shipped.criticUpdatesPerEpisode, recipeFolder == "stage1" ? 2 : 1);
      expected.seed = seed;
      EXPECT_EQ(shipped.seed, seed);
      EXPECT_EQ(trajectorySettings(shipped), trajectorySettings(expected));
      EXPECT_EQ(shipped.episodes, expected.episodes);
    }
  }
}
