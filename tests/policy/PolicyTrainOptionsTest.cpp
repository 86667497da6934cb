#include "passageMesh/policy/PolicyTrainOptions.hpp"

#include <gtest/gtest.h>

#include "../TestFiles.hpp"
#include "passageMesh/core/InputError.hpp"

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
  EXPECT_EQ(back.wideNoiseSigma, 0.4);
  EXPECT_EQ(readPolicyTrainDict(file.parent_path() / "missing.xml").episodes, PolicyTrainOptions{}.episodes);
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
  EXPECT_NE(bad("<searchBudget>1</searchBudget>").find("must be in [2,"), std::string::npos);
  EXPECT_NE(bad("<wideNoiseShare>1.5</wideNoiseShare>").find("bad.xml:2: <wideNoiseShare> is a share of the episodes"),
            std::string::npos) << bad("<wideNoiseShare>1.5</wideNoiseShare>");
  EXPECT_NE(bad("<wideNoiseSigma>0</wideNoiseSigma>").find("bad.xml:2:"), std::string::npos);
  EXPECT_NE(bad("<epsiodes>10</epsiodes>").find("epsiodes"), std::string::npos);
  EXPECT_NE(bad("<batchEpisodes>3000000000</batchEpisodes>").find("must be in [1, 2147483647]"), std::string::npos);
  EXPECT_NE(bad("<minibatch>200</minibatch><bufferCapacity>100</bufferCapacity>").find("never start"),
            std::string::npos);
}

TEST(PolicyTrainOptions, EveryEnumeratedSettingReadsBackFromItsWord) {
  for (const CriticModel v :
       {CriticModel::reward, CriticModel::validityAndQuality, CriticModel::validityAndBoundedQuality})
    EXPECT_EQ(criticModelNamed(nameOf(v)), v);
  for (const EdgeRadiusDraw v : {EdgeRadiusDraw::uniform, EdgeRadiusDraw::halfLogUniform})
    EXPECT_EQ(edgeRadiusDrawNamed(nameOf(v)), v);
  for (const ActorStart v : {ActorStart::random, ActorStart::defaults}) EXPECT_EQ(actorStartNamed(nameOf(v)), v);
  EXPECT_EQ(nameOf(CriticModel::validityAndQuality), "validityAndQuality");
  try {
    edgeRadiusDrawNamed("Uniform");  // words are case-sensitive, as in the dictionary
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "<edgeRadii> is 'halfLogUniform' or 'uniform', not 'Uniform'");
  }
}
