// iterOptimize as a user runs it, on a small case (nO 3000: a mesh in a few hundredths of a
// second): the history, the best parameters in meshDict.xml (the user's own kept once as
// meshDict.xml.orig), determinism, bad input, and Ctrl-C.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

#include "../blade/BladeTestData.hpp"
#include "UtilityTestSupport.hpp"
#include "passageMesh/blade/BladeParametersFile.hpp"
#include "passageMesh/core/NumberFormat.hpp"
#include "passageMesh/passage/PassageCase.hpp"
#include "passageMesh/workflow/MeshQualityObjective.hpp"

extern char** environ;

using namespace passageMesh;
using namespace passageMesh::testData;

namespace {

namespace fs = std::filesystem;

const std::string iterOptimize = ITEROPTIMIZE_EXECUTABLE;
const std::string startMeshDict = "<meshDict><nT>100</nT></meshDict>\n";

std::string passageDict(const std::string& nO) {
  return "<passageDict>\n<pitch>0.85c</pitch>\n<xIn>0.5c</xIn>\n<xOut>0.5c</xOut>\n<nO>" + nO +
         "</nO>\n<firstCellHeight>1.1e-4c</firstCellHeight>\n</passageDict>\n";
}

// The typical turbine blade at pitch 0.85c with 3000 O-block nodes: its default mesh with
// nT = 100 is valid (Q about 0.34) and many others in the box fold, as at full size.
fs::path smallCase(const std::string& name, const std::string& meshDict = startMeshDict,
                   const std::string& nO = "3000") {
  const auto dir = freshCase("iterOptimize_" + name);
  writeBladeParametersFile(dir / "constant" / "bladeParameters.xml", typicalTurbineBlade(), {});
  writeText(dir / "system" / "passageDict.xml", passageDict(nO));
  if (!meshDict.empty()) writeText(dir / "system" / "meshDict.xml", meshDict);
  return dir;
}

fs::path historyFile(const fs::path& dir) { return dir / "postProcessing" / "iterOptimize" / "history.csv"; }

// history.csv: the header and one row of numbers per evaluation.
struct History {
  std::string header;
  std::vector<std::vector<double>> rows;
};

History readHistory(const fs::path& dir) {
  std::istringstream in(readText(historyFile(dir)));
  History h;
  std::getline(in, h.header);
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    h.rows.push_back(row);
  }
  return h;
}

constexpr int qColumn = 11, bestColumn = 12;  // evaluation, 10 parameters, Q, bestQ

MeshingParameters parametersOf(const std::vector<double>& row) {
  std::array<double, MeshingParameters::size> v;
  for (int k = 0; k < MeshingParameters::size; ++k) v[k] = row[1 + k];
  return MeshingParameters::fromArray(v);
}

void expectSameParameters(const MeshingParameters& a, const MeshingParameters& b) {
  const auto x = a.toArray(), y = b.toArray();
  for (int k = 0; k < MeshingParameters::size; ++k)
    EXPECT_EQ(x[k], y[k]) << MeshingParameters::names()[k];
}

// The best-so-far column is the running maximum of Q, row by row; returns the best row.
std::size_t expectRunningBest(const History& h) {
  double best = -INFINITY;
  std::size_t bestRow = 0;
  for (std::size_t r = 0; r < h.rows.size(); ++r) {
    EXPECT_EQ(h.rows[r][0], static_cast<double>(r));
    if (h.rows[r][qColumn] > best) bestRow = r;
    best = std::max(best, h.rows[r][qColumn]);
    EXPECT_EQ(h.rows[r][bestColumn], best) << "row " << r;
  }
  return bestRow;
}

MeshingParameters meshDictOf(const fs::path& dir) {
  return readMeshDict(dir / "system" / "meshDict.xml", typicalTurbineBlade().chord);
}

// What the tool leaves when it refuses to run: the input as it was, no outputs.
void expectUntouched(const fs::path& dir, const std::string& meshDict) {
  EXPECT_FALSE(fs::exists(dir / "postProcessing"));
  EXPECT_FALSE(fs::exists(dir / "system" / "meshDict.xml.orig"));
  EXPECT_EQ(readText(dir / "system" / "meshDict.xml"), meshDict);
}

pid_t startTool(const fs::path& dir, const std::vector<std::string>& arguments) {
  return startInBackground(iterOptimize, dir, arguments);
}

}  // namespace

TEST(IterOptimizeCommand, WritesTheBestParametersAndTheHistory) {
  const auto dir = smallCase("good");
  const RunResult r = runTool(iterOptimize, dir, "-budget 12 -threads 2");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("12/12 evaluations"), std::string::npos) << r.err;

  const History h = readHistory(dir);
  EXPECT_EQ(h.header, "evaluation,yIn,yOut,alphaCamber,betaIn,betaOut,nT,gammaLE,gammaTE,splitIn,splitOut,Q,bestQ");
  ASSERT_EQ(h.rows.size(), 12u);
  const std::size_t best = expectRunningBest(h);

  // The first evaluation is the start, the case's meshDict (now kept as the .orig), and
  // its Q is the mesh's.
  PassageCase input = readPassageCase(dir, "test");
  const MeshingParameters start =
      readMeshDict(dir / "system" / "meshDict.xml.orig", input.blade.parameters().chord);
  expectSameParameters(parametersOf(h.rows[0]), start);
  EXPECT_EQ(h.rows[0][qColumn], meshQualityOf(input, start));
  EXPECT_GT(h.rows[0][qColumn], 0.2);
  EXPECT_GE(h.rows[best][qColumn], h.rows[0][qColumn]);

  // meshDict.xml holds the best row, read back exactly; the user's file is kept.
  expectSameParameters(meshDictOf(dir), parametersOf(h.rows[best]));
  EXPECT_EQ(readText(dir / "system" / "meshDict.xml.orig"), startMeshDict);
  EXPECT_NE(r.out.find("best Q " + formatExact(h.rows[best][qColumn])), std::string::npos) << r.out;
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
    EXPECT_EQ(readText(dir / "postProcessing" / "iterOptimize" / "convergence.png").substr(1, 3), "PNG");
  }

  // A second run starts from the first one's best and leaves the .orig alone.
  const RunResult again = runTool(iterOptimize, dir, "-budget 12 -seed 2 -threads 2");
  ASSERT_EQ(again.exitCode, 0) << again.err;
  const History h2 = readHistory(dir);
  ASSERT_EQ(h2.rows.size(), 12u);
  expectSameParameters(parametersOf(h2.rows[0]), parametersOf(h.rows[best]));
  EXPECT_EQ(h2.rows[0][qColumn], h.rows[best][qColumn]);
  expectSameParameters(meshDictOf(dir), parametersOf(h2.rows[expectRunningBest(h2)]));
  EXPECT_EQ(readText(dir / "system" / "meshDict.xml.orig"), startMeshDict);
}

TEST(IterOptimizeCommand, WithoutMeshDictStartsFromTheDefaultsAndKeepsNoOrig) {
  const auto dir = smallCase("defaults", "", "4500");  // nT 300: 15 nodes off the wall
  const RunResult r = runTool(iterOptimize, dir, "-budget 3");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const History h = readHistory(dir);
  ASSERT_EQ(h.rows.size(), 3u);
  expectSameParameters(parametersOf(h.rows[0]), MeshingParameters::defaults(typicalTurbineBlade().chord));
  EXPECT_TRUE(fs::exists(dir / "system" / "meshDict.xml"));
  EXPECT_FALSE(fs::exists(dir / "system" / "meshDict.xml.orig"));
}

TEST(IterOptimizeCommand, TheSameSeedGivesTheSameHistoryWithAnyThreadCount) {
  const auto one = smallCase("seedOneThread"), two = smallCase("seedTwoThreads");
  ASSERT_EQ(runTool(iterOptimize, one, "-budget 12 -seed 7 -threads 1").exitCode, 0);
  ASSERT_EQ(runTool(iterOptimize, two, "-budget 12 -seed 7 -threads 2").exitCode, 0);
  EXPECT_EQ(readText(historyFile(one)), readText(historyFile(two)));
  const auto other = smallCase("seedOther");
  ASSERT_EQ(runTool(iterOptimize, other, "-budget 12 -seed 8 -threads 2").exitCode, 0);
  EXPECT_NE(readText(historyFile(one)), readText(historyFile(other)));
}

TEST(IterOptimizeCommand, EveryMethodUsesExactlyItsBudget) {
  for (const std::string method : {"cmaes", "bobyqa", "sbplx", "cobyla", "crs2lm", "isres"}) {
    const auto dir = smallCase("method_" + method);
    const RunResult r = runTool(iterOptimize, dir, "-method " + method + " -budget 6");
    ASSERT_EQ(r.exitCode, 0) << method << ": " << r.err;
    const History h = readHistory(dir);
    EXPECT_EQ(h.rows.size(), 6u) << method;
    expectRunningBest(h);
  }
  const RunResult help = runCommand(iterOptimize, "-help", tempFolder("utilityCases"));
  EXPECT_EQ(help.exitCode, 0);
  for (const std::string method : {"cmaes", "bobyqa", "sbplx", "cobyla", "crs2lm", "isres"})
    EXPECT_NE(help.out.find(method), std::string::npos) << help.out;
}

TEST(IterOptimizeCommand, RefusesBadInputAndWritesNothing) {
  struct Bad {
    std::string name, arguments, message;
  };
  const std::vector<Bad> cases = {
      {"unknownMethod", "-method newton", "unknown method 'newton'"},
      {"zeroBudget", "-budget 0", "-budget"},
      {"negativeThreads", "-threads=-1", "-threads"},
      {"strayWord", "-budget 12 cmaes", "command line"},
  };
  for (const auto& bad : cases) {
    const auto dir = smallCase("bad_" + bad.name);
    const RunResult r = runTool(iterOptimize, dir, bad.arguments);
    EXPECT_EQ(r.exitCode, 1) << bad.name;
    EXPECT_EQ(r.err.rfind("iterOptimize: error: ", 0), 0u) << bad.name << ": " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << bad.name << ": " << r.err;  // one line
    EXPECT_NE(r.err.find(bad.message), std::string::npos) << bad.name << ": " << r.err;
    expectUntouched(dir, startMeshDict);
  }
  const auto noBlade = smallCase("bad_noBlade");
  fs::remove(noBlade / "constant" / "bladeParameters.xml");
  const RunResult r = runTool(iterOptimize, noBlade, "-budget 12");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("bladeParameters.xml: file not found"), std::string::npos) << r.err;
  expectUntouched(noBlade, startMeshDict);
}

TEST(IterOptimizeCommand, NoValidMeshKeepsMeshDictAndExits2) {
  // nT = 200 at nO = 2000 gives a node with J <= 0; a budget of 1 tries only that start.
  const std::string invalidStart = "<meshDict><nT>200</nT></meshDict>\n";
  const auto dir = smallCase("invalidStart", invalidStart, "2000");
  const RunResult r = runTool(iterOptimize, dir, "-budget 1");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("no valid mesh found"), std::string::npos) << r.err;
  EXPECT_EQ(readText(dir / "system" / "meshDict.xml"), invalidStart);
  EXPECT_FALSE(fs::exists(dir / "system" / "meshDict.xml.orig"));
  const History h = readHistory(dir);
  ASSERT_EQ(h.rows.size(), 1u);
  EXPECT_EQ(h.rows[0][qColumn], -1.0);
}

TEST(IterOptimizeCommand, CtrlCWritesTheBestSoFarAndExits130) {
  const auto dir = smallCase("interrupted");
  const long budget = 5000;  // minutes of meshes: the run must end by the interruption
  const pid_t pid = startTool(dir, {"-budget", std::to_string(budget), "-threads", "2"});
  ASSERT_GT(pid, 0);
  // The first progress line comes after the first batch: the run is under way.
  expectInterruptedWith130(pid, dir / "stderr.txt", "evaluations, best Q");
  if (HasFatalFailure()) return;
  const std::string err = readText(dir / "stderr.txt");
  EXPECT_NE(err.find("iterOptimize: interrupted after"), std::string::npos) << err;

  const History h = readHistory(dir);
  ASSERT_GE(h.rows.size(), 1u);
  EXPECT_LT(h.rows.size(), static_cast<std::size_t>(budget));
  const std::size_t best = expectRunningBest(h);
  expectSameParameters(meshDictOf(dir), parametersOf(h.rows[best]));
  EXPECT_EQ(readText(dir / "system" / "meshDict.xml.orig"), startMeshDict);
}

TEST(IterOptimizeCommand, ASecondCtrlCAbortsAndLeavesACompleteMeshDict) {
  const auto dir = smallCase("aborted");
  const pid_t pid = startTool(dir, {"-budget", "5000", "-threads", "2"});
  ASSERT_GT(pid, 0);
  const bool started = waitForText(dir / "stderr.txt", "evaluations, best Q", std::chrono::seconds(60));
  kill(pid, SIGINT);
  // Apart, so that the two signals are not merged into one pending signal.
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  kill(pid, SIGINT);
  const int status = waitForExit(pid, std::chrono::seconds(60));
  ASSERT_TRUE(started);
  ASSERT_NE(status, -1);
  // Killed by the second SIGINT, or (when the first one's batch and files were already
  // done) ended by the first with 130; either way meshDict.xml is a complete dictionary.
  const bool killed = WIFSIGNALED(status) && WTERMSIG(status) == SIGINT;
  const bool interrupted = WIFEXITED(status) && WEXITSTATUS(status) == 130;
  EXPECT_TRUE(killed || interrupted) << status;
  EXPECT_NO_THROW(meshDictOf(dir));
}
