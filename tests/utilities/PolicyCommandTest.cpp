// policyTrain and policyMesh as a user runs them: files, -resume after SIGKILL, MPI ranks,
// bad input.
#include <gtest/gtest.h>

#include <limits>
#include <regex>
#include <sstream>

#include "../blade/BladeTestData.hpp"
#include "UtilityTestSupport.hpp"
#include "passageMesh/blade/BladeParametersFile.hpp"
#include "passageMesh/policy/Policy.hpp"
#include "passageMesh/policy/PolicyEnvironment.hpp"
#include "passageMesh/policy/PolicyNetworks.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;
namespace fs = std::filesystem;

namespace {

const std::string policyTrain = POLICYTRAIN_EXECUTABLE;
const std::string policyMesh = POLICYMESH_EXECUTABLE;

// A short training on small networks: checkpoints every 32 episodes.
fs::path trainingCase(const std::string& name, long episodes, const std::string& extraKeys = "") {
  const fs::path dir = freshCase(name);
  writeText(dir / "system" / "policyTrainDict.xml",
            "<policyTrainDict>\n  <episodes>" + std::to_string(episodes) +
                "</episodes>\n  <batchEpisodes>16</batchEpisodes>\n  <minibatch>20</minibatch>\n"
                "  <hiddenLayers>32 32</hiddenLayers>\n  <validationEvery>64</validationEvery>\n"
                "  <validationPassages>6</validationPassages>\n  <checkpointEvery>32</checkpointEvery>\n"
                "  <logEvery>16</logEvery>\n  <threads>2</threads>\n" + extraKeys + "</policyTrainDict>\n");
  return dir;
}

// A case policyMesh can mesh: the typical turbine blade at a mid-range condition.
fs::path meshCase(const std::string& name) {
  const fs::path dir = freshCase(name);
  writeBladeParametersFile(dir / "constant" / "bladeParameters.xml", typicalTurbineBlade(), {});
  writeText(dir / "system" / "passageDict.xml",
            "<passageDict><pitch>0.7c</pitch><xIn>0.5c</xIn><xOut>0.5c</xOut><nO>12000</nO>"
            "<firstCellHeight>1e-4c</firstCellHeight></passageDict>\n");
  return dir;
}

// Passage `episode` of policyTrain's validation stream (20261202) as a case.
fs::path validationPassageCase(const std::string& name, long episode) {
  const PassageCase passage = PassageEnvironment().passage(20261202, episode);
  const fs::path dir = freshCase(name);
  writeBladeParametersFile(dir / "constant" / "bladeParameters.xml", passage.blade.parameters(), {});
  const PassageCondition& c = passage.condition;
  std::ostringstream dict;
  dict.precision(17);
  dict << "<passageDict><pitch>" << c.pitch << "</pitch><xIn>" << c.xIn << "</xIn><xOut>" << c.xOut
       << "</xOut><nO>" << c.nO << "</nO><firstCellHeight>" << c.firstCellHeight
       << "</firstCellHeight></passageDict>\n";
  writeText(dir / "system" / "passageDict.xml", dict.str());
  return dir;
}

}  // namespace

TEST(PolicyTrainCommand, WritesPolicyCheckpointAndCurvesAndResumesBitForBitAfterSigkill) {
  const fs::path straight = trainingCase("policyTrainStraight", 256);
  const RunResult r = runTool(policyTrain, straight);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* f : {"policy/policy.xml", "policy/policy.pt", "policy/final.xml", "policy/final.pt",
                        "policy/checkpoint.pt", "postProcessing/policyTrain/learning.csv",
                        "postProcessing/policyTrain/validation.csv"})
    EXPECT_TRUE(fs::exists(straight / f)) << f;
  EXPECT_NE(r.err.find("256/256 episodes"), std::string::npos) << r.err;
  const std::string validation = readText(straight / "postProcessing/policyTrain/validation.csv");
  EXPECT_EQ(validation.rfind("episode,meanReward,medianReward,valid,passages\n64,", 0), 0u) << validation;

  // A second run of the same case refuses to overwrite the checkpoint.
  const RunResult again = runTool(policyTrain, straight);
  EXPECT_EQ(again.exitCode, 1);
  EXPECT_NE(again.err.find("-resume"), std::string::npos) << again.err;

  // Killed (SIGKILL) after its first checkpoint, then resumed: the same final weights.
  const fs::path killed = trainingCase("policyTrainKilled", 256);
  const pid_t pid = startInBackground(policyTrain, killed, {});
  ASSERT_GT(pid, 0);
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(killed / "policy" / "checkpoint.pt") && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed; make it longer";
  EXPECT_FALSE(fs::exists(killed / "policy" / "final.pt"));
  const RunResult resumed = runTool(policyTrain, killed, "-resume");
  ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("resumed at episode"), std::string::npos) << resumed.out;
  EXPECT_EQ(readText(killed / "policy" / "final.pt"), readText(straight / "policy" / "final.pt"));
  EXPECT_EQ(readText(killed / "postProcessing/policyTrain/validation.csv"), validation);
}

TEST(PolicyTrainCommand, StartFromContinuesAnotherRunWithThisCasesSettings) {
  const fs::path base = trainingCase("policyTrainBase", 32);
  ASSERT_EQ(runTool(policyTrain, base).exitCode, 0);
  const fs::path next = trainingCase("policyTrainNext", 64, "  <searchEvery>16</searchEvery>\n  <searchBudget>8</searchBudget>\n");
  const std::string from = "-startFrom '" + (base / "policy" / "checkpoint.pt").string() + "'";
  const RunResult both = runTool(policyTrain, next, from + " -resume");
  EXPECT_EQ(both.exitCode, 1);
  EXPECT_NE(both.err.find("give one"), std::string::npos) << both.err;
  const RunResult r = runTool(policyTrain, next, from);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("started at episode 32"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("2 searches"), std::string::npos) << r.err;
  const RunResult missing = runTool(policyTrain, trainingCase("policyTrainNoBase", 64), "-startFrom nowhere.pt");
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("nowhere.pt"), std::string::npos) << missing.err;
}

TEST(PolicyTrainCommand, TwoMpiRanksGiveTheWeightsOfTwoThreads) {
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0) GTEST_SKIP() << "no mpirun";
  // Open MPI refuses root without these (CI runs as root) and two ranks on few cores.
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  setenv("OMPI_MCA_rmaps_base_oversubscribe", "1", 1);
  // The same 64 episodes on two threads and on two ranks of one thread each: the same bytes.
  const auto expectRanksGiveThreadsWeights = [](const std::string& name, const std::string& keys) {
    SCOPED_TRACE(name);
    const fs::path threads = trainingCase(name + "Threads", 64, keys);
    ASSERT_EQ(runTool(policyTrain, threads).exitCode, 0);
    const fs::path ranks = trainingCase(name + "Ranks", 64, keys);
    const RunResult r = runCommand("mpirun", "-np 2 '" + policyTrain + "' -case '" + ranks.string() +
                                                 "' -parallel -threads 1", ranks);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("2 MPI ranks"), std::string::npos) << r.out;
    EXPECT_EQ(readText(ranks / "policy" / "final.pt"), readText(threads / "policy" / "final.pt"));
  };
  // With searches: their batches (every row the same passage) go over the ranks too.
  expectRanksGiveThreadsWeights("policyTrainSearches", "  <searchEvery>32</searchEvery>\n  <searchBudget>12</searchBudget>\n"
                                                       "  <imitationWeight>1</imitationWeight>\n");
  // The learner beside the next batch's rollouts: on rank 0 it runs while the ranks mesh.
  expectRanksGiveThreadsWeights("policyTrainLearnDuringRollouts",
                                "  <learnerSchedule>duringNextRollouts</learnerSchedule>\n");
}

TEST(PolicyMeshCommand, MeshesWithATrainedPolicyAndRefusesBadPolicyFiles) {
  const fs::path trained = trainingCase("policyForMesh", 32);
  ASSERT_EQ(runTool(policyTrain, trained).exitCode, 0);
  const fs::path policyXml = trained / "policy" / "final.xml";

  const fs::path dir = meshCase("policyMesh");
  const RunResult r = runTool(policyMesh, dir, "-policy '" + policyXml.string() + "'");
  // An untrained policy may well fold the mesh; either way the parameters are printed and
  // the outcome is reported on one line. meshDict.xml is written with the mesh, or not at all.
  EXPECT_NE(r.out.find("forward pass"), std::string::npos) << r.out;
  // What the file records of its training: the run's episodes and its validation.
  EXPECT_NE(r.out.find("(32 episodes in the run that wrote it, validation mean reward "), std::string::npos) << r.out;
  if (r.exitCode == 0) {
    EXPECT_NE(r.out.find("policyMesh: Q = "), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(dir / "mesh" / "passage.cgns"));
    EXPECT_TRUE(fs::exists(dir / "system" / "meshDict.xml"));
  } else {
    EXPECT_NE(r.err.find("the mesh is invalid"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "mesh" / "passage.cgns"));
    EXPECT_FALSE(fs::exists(dir / "system" / "meshDict.xml"));
  }

  // An ensemble of the policy with itself acts as the policy: the same meshing parameters.
  const fs::path ensembleXml = trained / "policy" / "twice.xml";
  writeText(ensembleXml, "<policy><format>passageMesh policy ensemble 1</format>"
                         "<members>final.xml final.xml</members></policy>\n");
  const fs::path twice = meshCase("policyMeshEnsemble");
  const RunResult e = runTool(policyMesh, twice, "-policy '" + ensembleXml.string() + "'");
  EXPECT_EQ(e.exitCode, r.exitCode) << e.err;
  // Not "trained in 64 episodes": members' episode counts do not add up to a training.
  EXPECT_NE(e.out.find("(an ensemble of 2 members)"), std::string::npos) << e.out;
  const auto parameterLines = [](const std::string& out) {  // "    name value", as printed
    std::string lines;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("    ", 0) == 0) lines += line + "\n";
    return lines;
  };
  EXPECT_NE(parameterLines(r.out).find("nT"), std::string::npos) << r.out;
  EXPECT_EQ(parameterLines(e.out), parameterLines(r.out));

  const auto refused = [&](const std::string& name, const std::string& policyArgument,
                           const std::string& expected) {
    const fs::path c = meshCase(name);
    const RunResult bad = runTool(policyMesh, c, "-policy '" + policyArgument + "'");
    EXPECT_EQ(bad.exitCode, 1) << name;
    EXPECT_NE(bad.err.find(expected), std::string::npos) << name << ": " << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    EXPECT_FALSE(fs::exists(c / "system" / "meshDict.xml")) << name;
    EXPECT_FALSE(fs::exists(c / "mesh")) << name;
  };
  refused("missingPolicy", (trained / "policy" / "nothing.xml").string(), "nothing.xml: no such policy file");

  const fs::path corrupt = trained / "corrupt";
  fs::create_directories(corrupt);
  fs::copy_file(policyXml, corrupt / "final.xml");
  writeText(corrupt / "final.pt", "garbage");
  refused("corruptActor", (corrupt / "final.xml").string(), "final.pt");

  // A diverged actor: one weight NaN, the file otherwise sound.
  const fs::path diverged = trained / "diverged";
  fs::create_directories(diverged);
  fs::copy_file(policyXml, diverged / "final.xml");
  {
    FullyConnected actor = makeActor(Policy::load(policyXml).layout());
    torch::serialize::InputArchive in;
    in.load_from((trained / "policy" / "final.pt").string());
    actor->load(in);
    torch::NoGradGuard noGrad;
    actor->parameters()[2].view(-1)[0] = std::numeric_limits<float>::quiet_NaN();
    torch::serialize::OutputArchive out;
    actor->save(out);
    out.save_to((diverged / "final.pt").string());
  }
  refused("divergedActor", (diverged / "final.xml").string(), "final.pt: the actor's layers.2.weight holds NaN");

  // Bytes changed inside a tensor, the ZIP's structure intact: LibTorch would load it.
  const fs::path flipped = trained / "flipped";
  fs::create_directories(flipped);
  fs::copy_file(policyXml, flipped / "final.xml");
  fs::copy_file(trained / "policy" / "final.pt", flipped / "final.pt");
  testData::flipATensorByte(flipped / "final.pt");
  refused("flippedActor", (flipped / "final.xml").string(), "' does not match its checksum (the file is corrupt)");

  const fs::path wider = trained / "wider";
  fs::create_directories(wider);
  std::string xml = readText(policyXml);
  xml.replace(xml.find("<hiddenLayers>32 32<"), 20, "<hiddenLayers>32 64<");
  writeText(wider / "final.xml", xml);
  fs::copy_file(trained / "policy" / "final.pt", wider / "final.pt");
  refused("layoutMismatch", (wider / "final.xml").string(), "not an actor of the layout");

  const fs::path otherRange = trained / "otherRange";
  fs::create_directories(otherRange);
  xml = readText(policyXml);
  xml.replace(xml.find("<actionUpper>0.5 "), 17, "<actionUpper>0.6 ");
  writeText(otherRange / "final.xml", xml);
  fs::copy_file(trained / "policy" / "final.pt", otherRange / "final.pt");
  refused("scalingMismatch", (otherRange / "final.xml").string(), "actionUpper");

  // policyTrain writes the edge radii on a log scale (format 2); a scale word it does not know is refused.
  xml = readText(policyXml);
  EXPECT_NE(xml.find("<format>passageMesh policy 2</format>"), std::string::npos) << xml;
  const std::string logRadii = "linear linear log log linear";
  ASSERT_NE(xml.find(logRadii), std::string::npos) << xml;
  const fs::path badScale = trained / "badScale";
  fs::create_directories(badScale);
  xml.replace(xml.find(logRadii), logRadii.size(), "linear linear log cubic linear");
  writeText(badScale / "final.xml", xml);
  fs::copy_file(trained / "policy" / "final.pt", badScale / "final.pt");
  refused("badStateScale", (badScale / "final.xml").string(), "<stateScale> expects 24 words");
}

// The shipped ensemble's mean action folds validation passage 3 (policyTrain's stream
// 20261202), which a member's own action meshes (docs/policy.md "Members' own actions where
// the mean folds"): policyMesh says so and keeps that member's mesh, the one the member
// alone gives.
TEST(PolicyMeshCommand, FallsBackOnAMembersOwnActionWhereTheShippedEnsemblesMeanFolds) {
  const fs::path shipped = validationPassageCase("policyMeshFallback", 3);
  const RunResult r = runTool(policyMesh, shipped);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  int member = 0;
  const std::regex fellBack("member ([0-9]+)'s own action instead");
  for (std::sregex_iterator m(r.out.begin(), r.out.end(), fellBack), end; m != end; ++m)
    member = std::stoi((*m)[1]);
  ASSERT_GT(member, 0) << "the shipped ensemble's mean action meshes validation passage 3: choose a passage "
                          "where it folds for this test\n" << r.out;

  // The member's own file, from the ensemble's list.
  const fs::path policies = fs::path(PASSAGEMESH_SOURCE_DIR) / "etc" / "policy";
  std::smatch listed;
  const std::string ensemble = readText(policies / "policy.xml");
  ASSERT_TRUE(std::regex_search(ensemble, listed, std::regex("<members>([^<]*)</members>")));
  std::istringstream names(listed[1].str());
  std::string name;
  for (int i = 0; i < member; ++i) ASSERT_TRUE(static_cast<bool>(names >> name)) << listed[1];
  const fs::path alone = validationPassageCase("policyMeshFallbackMember", 3);
  const RunResult m = runTool(policyMesh, alone, "-policy '" + (policies / name).string() + "'");
  ASSERT_EQ(m.exitCode, 0) << m.err;
  EXPECT_EQ(m.out.find("own action instead"), std::string::npos) << m.out;
  EXPECT_EQ(readText(shipped / "system" / "meshDict.xml"), readText(alone / "system" / "meshDict.xml"));
  const auto qLine = [](const std::string& out) { return out.substr(out.find("policyMesh: Q = ")); };
  ASSERT_NE(m.out.find("policyMesh: Q = "), std::string::npos) << m.out;
  EXPECT_EQ(qLine(r.out), qLine(m.out));
  EXPECT_TRUE(fs::exists(shipped / "mesh" / "passage.cgns"));
}

// Validation passage 168 (pitch 0.99 chord, the outlet 0.003 chord behind the trailing
// edge): the shipped ensemble's mean action and each member's own fold it, as do the
// parameter moves. An invalid mesh is an error on one line, and the case is left as it
// was: no meshDict.xml without its mesh.
TEST(PolicyMeshCommand, AnInvalidMeshIsAnErrorAndWritesNothing) {
  const fs::path dir = validationPassageCase("policyMeshInvalid", 168);
  const RunResult r = runTool(policyMesh, dir);
  ASSERT_NE(r.exitCode, 0) << "the shipped policy meshes validation passage 168: choose a passage where "
                              "it does not for this test\n" << r.out;
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("policyMesh: error: the mesh is invalid"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("    nT "), std::string::npos) << r.out;  // the parameters are printed
  EXPECT_FALSE(fs::exists(dir / "system" / "meshDict.xml"));
  EXPECT_FALSE(fs::exists(dir / "mesh"));
}

// Validation passage 11: its blade is wider in y (1.04 pitches) than the pitch, so it
// would overlap its periodic neighbour. Reading the case says so, naming the file and the
// pitch's line; nothing is meshed or written.
TEST(PolicyMeshCommand, APitchAtWhichTheBladeOverlapsItsNeighbourIsRefused) {
  const fs::path dir = validationPassageCase("policyMeshOverlap", 11);
  const RunResult r = runTool(policyMesh, dir);
  EXPECT_EQ(r.exitCode, 1) << r.out;
  EXPECT_NE(r.err.find((dir / "system" / "passageDict.xml").string() + ":"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("<pitch>"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the blade overlaps its periodic neighbour: no passage exists"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "system" / "meshDict.xml"));
  EXPECT_FALSE(fs::exists(dir / "mesh"));
}
