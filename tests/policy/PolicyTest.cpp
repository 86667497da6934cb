// Policy files: an ensemble's action is the mean of its members' actions, its episodes
// their sum; ill-formed ensembles are refused with the file named; policies written before
// the splits were meshing parameters are read with them at 0.
#include "passageMesh/policy/Policy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <filesystem>
#include <string>
#include <vector>

#include "../TestFiles.hpp"
#include "passageMesh/blade/BladeSampler.hpp"
#include "passageMesh/core/InputError.hpp"

using namespace passageMesh;
namespace fs = std::filesystem;

namespace {

// A small untrained actor's policy files in DIR/NAME/policy.xml (+ .pt).
fs::path writeMember(const fs::path& dir, const std::string& name, std::uint64_t seed, long episodes,
                     EdgeRadiusScale edgeRadii = EdgeRadiusScale::logarithmic) {
  NetworkLayout layout{policyStateSize, policyActionSize, {16, 16}, 0.01, CriticModel::reward};
  const ActorCritic learner(layout, LearningRates{}, seed);
  fs::create_directories(dir / name);
  const fs::path xml = dir / name / "policy.xml";
  writePolicyFiles(xml, learner, policyStateScaling(BladeParameterRange::readDefault(), edgeRadii),
                   PolicyProvenance{episodes, 0.5, "test"});
  return xml;
}

fs::path writeEnsemble(const fs::path& dir, const std::string& name, const std::string& members,
                       const std::string& extra = "") {
  const fs::path xml = dir / name;
  std::ofstream(xml) << "<policy>\n  <format>passageMesh policy ensemble 1</format>\n  <members>" << members
                     << "</members>\n" << extra << "</policy>\n";
  return xml;
}

std::string loadError(const fs::path& xml) {
  try {
    Policy::load(xml);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

PolicyState someState(int n) {
  PolicyState s;
  for (int k = 0; k < policyStateSize; ++k) s[k] = std::sin(0.7 * n + 1.3 * k);
  return s;
}

}  // namespace

TEST(Policy, AnEnsemblesActionIsTheMeanOfItsMembersActions) {
  const fs::path dir = testData::tempFolder("policyEnsemble");
  writeMember(dir, "a", 1, 100);
  writeMember(dir, "b", 2, 250);
  const Policy a = Policy::load(dir / "a" / "policy.xml"), b = Policy::load(dir / "b" / "policy.xml");
  const Policy both = Policy::load(writeEnsemble(dir, "both.xml", "a/policy.xml\n    b/policy.xml",
                                                 "  <validationMeanReward>0.25</validationMeanReward>\n"));
  EXPECT_EQ(a.memberCount(), 1);
  EXPECT_EQ(both.memberCount(), 2);
  EXPECT_EQ(both.provenance().episodes, 350);
  EXPECT_EQ(both.provenance().validationMeanReward, 0.25);
  int differ = 0;
  for (int n = 0; n < 5; ++n) {
    const PolicyState s = someState(n);
    const PolicyAction x = a.act(s), y = b.act(s), mean = both.act(s);
    for (int k = 0; k < policyActionSize; ++k) {
      EXPECT_EQ(mean[k], (x[k] + y[k]) / 2) << n << " " << k;
      differ += x[k] != y[k];
    }
  }
  EXPECT_GT(differ, 0) << "the two members act alike: the mean shows nothing";
  // A member alone acts as its own file does.
  const Policy onlyA = Policy::load(writeEnsemble(dir, "onlyA.xml", "a/policy.xml"));
  for (int n = 0; n < 3; ++n) EXPECT_EQ(onlyA.act(someState(n)), a.act(someState(n)));

  // The actions policyMesh tries in turn: the mean, then each member's own; a single
  // actor (or an ensemble of one) has only its own.
  const std::vector<PolicyAction> inTurn = both.actionsInTurn(someState(7));
  ASSERT_EQ(inTurn.size(), 3u);
  EXPECT_EQ(inTurn[0], both.act(someState(7)));
  EXPECT_EQ(inTurn[1], a.act(someState(7)));
  EXPECT_EQ(inTurn[2], b.act(someState(7)));
  EXPECT_EQ(a.actionsInTurn(someState(7)), std::vector<PolicyAction>{a.act(someState(7))});
  EXPECT_EQ(onlyA.actionsInTurn(someState(7)).size(), 1u);
}

TEST(Policy, AnIllFormedEnsembleIsRefusedWithItsFileNamed) {
  const fs::path dir = testData::tempFolder("policyEnsembleRefused");
  writeMember(dir, "a", 1, 100);
  writeMember(dir, "linear", 3, 100, EdgeRadiusScale::linear);
  const auto expectError = [](const fs::path& xml, const std::string& expected) {
    const std::string e = loadError(xml);
    EXPECT_NE(e.find(expected), std::string::npos) << e;
    EXPECT_NE(e.find(xml.filename().string()), std::string::npos) << e;
  };
  expectError(writeEnsemble(dir, "missing.xml", "a/policy.xml nothing/policy.xml"), "does not exist");
  expectError(writeEnsemble(dir, "empty.xml", " "), "one or more member");
  expectError(writeEnsemble(dir, "withLayers.xml", "a/policy.xml", "<hiddenLayers>16 16</hiddenLayers>\n"),
              "belongs to a member's file");
  writeEnsemble(dir, "inner.xml", "a/policy.xml");
  const std::string nested = loadError(writeEnsemble(dir, "nested.xml", "inner.xml"));
  EXPECT_NE(nested.find("inner.xml"), std::string::npos) << nested;
  EXPECT_NE(nested.find("a single policy"), std::string::npos) << nested;
  const std::string scales = loadError(writeEnsemble(dir, "scales.xml", "a/policy.xml linear/policy.xml"));
  EXPECT_NE(scales.find("linear/policy.xml:"), std::string::npos) << scales;  // the member that differs
  EXPECT_NE(scales.find("<stateScale> differs from the first member's (a/policy.xml)"), std::string::npos) << scales;
  // <members> in a single policy's file.
  std::string single;
  {
    std::ifstream in(dir / "a" / "policy.xml");
    single.assign(std::istreambuf_iterator<char>(in), {});
  }
  single.replace(single.find("</policy>"), 9, "<members>a/policy.xml</members>\n</policy>");
  std::ofstream(dir / "a" / "withMembers.xml") << single;
  expectError(dir / "a" / "withMembers.xml", "<members> belongs to an ensemble's file");
}

// A policy written before the splits were meshing parameters (tests/policy/data/eightActions:
// a shipped member from 2026-12-04 to 2026-12-07) has the method's eight actions; it is still
// read, and its meshes have the splits at 0, the method's outer loop, exactly.
TEST(Policy, APolicyWithoutTheSplitsInItsActionMeshesWithThemAtZero) {
  const fs::path eightActions = fs::path(PASSAGEMESH_SOURCE_DIR) / "tests" / "policy" / "data" / "eightActions";
  const Policy old = Policy::load(eightActions / "policy.xml");
  EXPECT_EQ(old.layout().actionSize, MeshingParameters::methodSize);
  BladeSampler sampler(BladeParameterRange::readDefault(), 5);
  const BladeParameters blade = sampler.next();
  PassageCondition condition;
  condition.pitch = 0.8 * blade.chord;
  condition.xIn = condition.xOut = 0.5 * blade.chord;
  condition.firstCellHeight = 1.1e-4 * blade.chord;
  condition.nO = 30000;
  const PolicyAction a = old.act(old.state(blade, condition));
  EXPECT_EQ(a[8], 0.0);
  EXPECT_EQ(a[9], 0.0);
  const MeshingParameters p = old.meshingParameters(blade, condition);
  EXPECT_EQ(p.splitIn, 0.0);
  EXPECT_EQ(p.splitOut, 0.0);
  EXPECT_GT(std::abs(a[0]) + std::abs(a[5]), 0.0);  // the method's eight come from the network

  // A policy of this build has all ten.
  const auto dir = testData::tempFolder("policyTenActions");
  const Policy ten = Policy::load(writeMember(dir, "ten", 3, 1));
  EXPECT_EQ(ten.layout().actionSize, policyActionSize);
  EXPECT_EQ(policyActionSize, MeshingParameters::size);

  // In an ensemble of both, the method's eight are the mean of the two members and the
  // splits are the ten-action member's alone (the other knows nothing of them).
  fs::create_directories(dir / "old");
  for (const char* file : {"policy.xml", "policy.pt"})
    fs::copy_file(eightActions / file, dir / "old" / file,
                  fs::copy_options::overwrite_existing);
  const Policy mixed = Policy::load(writeEnsemble(dir, "mixed.xml", "old/policy.xml ten/policy.xml"));
  const PolicyState s = old.state(blade, condition);
  const PolicyAction x = old.act(s), y = ten.act(s), m = mixed.act(s);
  for (int k = 0; k < MeshingParameters::methodSize; ++k) EXPECT_EQ(m[k], (x[k] + y[k]) / 2) << k;
  EXPECT_EQ(m[8], y[8]);
  EXPECT_EQ(m[9], y[9]);
  EXPECT_NE(y[8], 0.0);
  // Tried on its own (policyMesh's turn after the mean), the eight-action member gives
  // the splits at 0, as alone.
  const std::vector<PolicyAction> inTurn = mixed.actionsInTurn(s);
  ASSERT_EQ(inTurn.size(), 3u);
  EXPECT_EQ(inTurn[1], x);
  EXPECT_EQ(inTurn[2], y);
}
