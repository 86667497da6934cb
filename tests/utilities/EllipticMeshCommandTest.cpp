// ellipticMesh as a user runs it: a case gives mesh/passage.cgns (which cgnscheck accepts,
// when it is installed) and mesh/passage.vtm, polished with -polish; bad input gives a
// one-line error, a non-zero exit and no mesh files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "../blade/BladeTestData.hpp"
#include "UtilityTestSupport.hpp"
#include "passageMesh/blade/BladeParametersFile.hpp"
#include "passageMesh/passage/PassageSampler.hpp"
#include "passageMesh/quality/MeshQuality.hpp"
#include "passageMesh/structured/CgnsReader.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;

namespace {

const std::string ellipticMesh = ELLIPTICMESH_EXECUTABLE;

std::string passageDict(const std::string& pitch, const std::string& nO = "12000") {
  return "<passageDict>\n<pitch>" + pitch + "</pitch>\n<xIn>0.5c</xIn>\n<xOut>0.5c</xOut>\n<nO>" +
         nO + "</nO>\n<firstCellHeight>1.1e-4c</firstCellHeight>\n</passageDict>\n";
}

std::filesystem::path caseWith(const std::string& name, const std::string& dict,
                               const std::string& meshDict = "") {
  const auto dir = freshCase("ellipticMesh_" + name);
  writeBladeParametersFile(dir / "constant" / "bladeParameters.xml", typicalTurbineBlade(), {});
  writeText(dir / "system" / "passageDict.xml", dict);
  if (!meshDict.empty()) writeText(dir / "system" / "meshDict.xml", meshDict);
  return dir;
}

void expectNoMesh(const std::filesystem::path& dir) {
  EXPECT_FALSE(std::filesystem::exists(dir / "mesh" / "passage.cgns"));
  EXPECT_FALSE(std::filesystem::exists(dir / "mesh" / "passage.vtm"));
}

}  // namespace

TEST(EllipticMeshCommand, WritesCgnsAndVtkThatCgnscheckAccepts) {
  const auto dir = caseWith("good", passageDict("0.85c"), "<meshDict><nT>150</nT></meshDict>");
  const RunResult r = runTool(ellipticMesh, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("converged"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir / "mesh" / "passage.cgns"));
  EXPECT_TRUE(std::filesystem::exists(dir / "mesh" / "passage.vtm"));
  EXPECT_TRUE(std::filesystem::exists(dir / "mesh" / "passage" / "OBlock.vts"));
  if (std::system("command -v cgnscheck > /dev/null 2>&1") != 0) GTEST_SKIP() << "no cgnscheck";
  std::string quoted = "'";  // (built in steps: GCC 12 warns falsely on the one-line concatenation)
  quoted += (dir / "mesh" / "passage.cgns").string();
  quoted += "'";
  const RunResult check = runCommand("cgnscheck", quoted, dir);
  EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
  EXPECT_EQ(check.out.find("WARNING"), std::string::npos) << check.out;
  EXPECT_EQ(check.out.find("ERROR"), std::string::npos) << check.out;
}

TEST(EllipticMeshCommand, RefusesBadInputAndWritesNothing) {
  struct Bad {
    std::string name, dict, meshDict, message;
  };
  const std::vector<Bad> cases = {
      {"negativePitch", passageDict("-0.01"), "", "expected a positive length"},
      {"fewNodes", passageDict("0.85c", "50"), "", "nO"},
      {"brokenMeshDict", passageDict("0.85c"), "<meshDict><nT>many</nT></meshDict>", "nT"},
  };
  for (const auto& bad : cases) {
    const auto dir = caseWith(bad.name, bad.dict, bad.meshDict);
    const RunResult r = runTool(ellipticMesh, dir);
    EXPECT_NE(r.exitCode, 0) << bad.name;
    EXPECT_NE(r.err.find(bad.message), std::string::npos) << bad.name << ": " << r.err;
    EXPECT_NE(r.err.find("ellipticMesh: error:"), std::string::npos) << r.err;
    expectNoMesh(dir);
  }
  const auto noBlade = freshCase("ellipticMesh_noBlade");
  writeText(noBlade / "system" / "passageDict.xml", passageDict("0.85c"));
  const RunResult r = runTool(ellipticMesh, noBlade);
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("bladeParameters.xml: file not found"), std::string::npos) << r.err;
  expectNoMesh(noBlade);
}

TEST(EllipticMeshCommand, ClipsOutOfRangeParametersWithAWarning) {
  const auto dir = caseWith("clipped", passageDict("0.85c"),
                            "<meshDict><nT>150</nT><betaIn>1.5</betaIn></meshDict>");
  const RunResult r = runTool(ellipticMesh, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("betaIn"), std::string::npos) << r.err;
}

TEST(EllipticMeshCommand, AFoldedMeshIsAnErrorAndWritesNothing) {
  // Draw 463 of the robustness sweep (seed 20261122; nT 159, 0.013 chord between the blade
  // and the outer loop): its smoothed lines fold, also with the outer loop moved away and
  // the node clustering moved to the defaults' (docs/benchmarks.md, robustness sweep).
  const PassageDraw d = samplePassages(500, 20261122)[463];
  const auto dir = freshCase("ellipticMesh_folded");
  writeBladeParametersFile(dir / "constant" / "bladeParameters.xml", d.blade, {});
  auto metres = [](double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v);
    return std::string(text);
  };
  writeText(dir / "system" / "passageDict.xml",
            "<passageDict><pitch>" + metres(d.condition.pitch) + "</pitch><xIn>" + metres(d.condition.xIn) +
                "</xIn><xOut>" + metres(d.condition.xOut) + "</xOut><nO>" + std::to_string(d.condition.nO) +
                "</nO><firstCellHeight>" + metres(d.condition.firstCellHeight) +
                "</firstCellHeight></passageDict>\n");
  writeText(dir / "system" / "meshDict.xml", meshDictXml(d.parameters));
  const RunResult r = runTool(ellipticMesh, dir);
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("the mesh is invalid: the smoothed lines fold"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("still invalid"), std::string::npos) << r.err;  // the moves were tried
  expectNoMesh(dir);
}

TEST(EllipticMeshCommand, APeriodicBoundaryThroughTheBladeIsAnErrorAndWritesNothing) {
  // Half a chord of offset at the inlet with a pitch of 0.3 chords: the lower periodic
  // boundary runs through the blade, no passage exists, nothing is smoothed.
  const auto dir = caseWith("cut", passageDict("0.3c"), "<meshDict><yIn>0.5c</yIn></meshDict>");
  const RunResult r = runTool(ellipticMesh, dir);
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("the lower periodic boundary cuts the blade at x = "), std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("not smoothed"), std::string::npos) << r.out;
  expectNoMesh(dir);
}

// A write that fails part way (a file size limit here, as a full disk would) ends in one
// line and exit code 1 and leaves the case's mesh files as they were: the CGNS and VTK
// files are replaced together or not at all. Before, HDF5's exit handler crashed the tool
// after its error line (SIGSEGV), and the new mesh's VTK files stood beside the old CGNS.
TEST(EllipticMeshCommand, AFailedWriteLeavesTheMeshFilesAsTheyWere) {
  const auto dir = caseWith("limited", passageDict("0.85c"), "<meshDict><nT>150</nT></meshDict>");
  ASSERT_EQ(runTool(ellipticMesh, dir).exitCode, 0);
  const std::vector<std::string> files = {"mesh/passage.cgns", "mesh/passage.vtm", "mesh/passage/OBlock.vts"};
  std::vector<std::string> before;
  for (const auto& f : files) before.push_back(readText(dir / f));
  writeText(dir / "system" / "passageDict.xml", passageDict("0.85c", "10000"));
  const RunResult r = runWithFileSizeLimit(ellipticMesh, "-case '" + dir.string() + "'", dir, 64);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_EQ(r.err.rfind("ellipticMesh: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("passage.cgns"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (std::size_t k = 0; k < files.size(); ++k) EXPECT_EQ(readText(dir / files[k]), before[k]) << files[k];
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir / "mesh"))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
}

// -polish: the written mesh is the polished one, with the Q the tool prints, above the
// unpolished mesh's; without it, the mesh is the elliptic one whose Q the polish started from.
TEST(EllipticMeshCommand, PolishWritesThePolishedMeshWithTheQualityItPrints) {
  const std::string dict = passageDict("0.85c", "4000");
  const std::string meshDict = "<meshDict><nT>100</nT></meshDict>";
  const auto plainDir = caseWith("plain", dict, meshDict), polishDir = caseWith("polish", dict, meshDict);
  const RunResult plain = runTool(ellipticMesh, plainDir);
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_EQ(plain.out.find("polish:"), std::string::npos) << plain.out;
  const RunResult polished = runTool(ellipticMesh, polishDir, "-polish");
  ASSERT_EQ(polished.exitCode, 0) << polished.err;
  double before = 0, after = 0;
  const auto line = polished.out.find("polish: Q ");
  ASSERT_NE(line, std::string::npos) << polished.out;
  ASSERT_EQ(std::sscanf(polished.out.c_str() + line, "polish: Q %lf -> %lf", &before, &after), 2) << polished.out;
  EXPECT_NE(polished.out.find(": kept"), std::string::npos) << polished.out;
  const double qPlain = computeMeshQuality(readCgns(plainDir / "mesh" / "passage.cgns")).Q;
  const double qPolished = computeMeshQuality(readCgns(polishDir / "mesh" / "passage.cgns")).Q;
  EXPECT_NEAR(qPlain, before, 1e-6);
  EXPECT_NEAR(qPolished, after, 1e-6);
  EXPECT_GT(qPolished, qPlain);
  // A line for each pass that raised Q, the whole O-block's first.
  EXPECT_NE(polished.out.find("polish pass 1, the whole O-block: Q "), std::string::npos) << polished.out;
}

// Ctrl-C during the polish (after its first pass) ends it early: the mesh is written with
// the best nodes so far (the Q printed, above the elliptic mesh's), and the exit code is 130.
TEST(EllipticMeshCommand, CtrlCDuringThePolishWritesTheMeshSoFarAndExits130) {
  const auto dir = caseWith("polishInterrupted", passageDict("0.85c", "4000"), "<meshDict><nT>100</nT></meshDict>");
  const pid_t pid = startInBackground(ellipticMesh, dir, {"-polish"});
  ASSERT_GT(pid, 0);
  // Printed when the whole-block pass has raised Q; the windows take seconds after it here.
  expectInterruptedWith130(pid, dir / "stdout.txt", "polish pass 1, the whole O-block");
  if (HasFatalFailure()) return;
  const std::string out = readText(dir / "stdout.txt");
  EXPECT_NE(out.find("interrupted (Ctrl-C)"), std::string::npos) << out;
  double before = 0, after = 0;
  const auto line = out.find("polish: Q ");
  ASSERT_NE(line, std::string::npos) << out;
  ASSERT_EQ(std::sscanf(out.c_str() + line, "polish: Q %lf -> %lf", &before, &after), 2) << out;
  const MeshQuality q = computeMeshQuality(readCgns(dir / "mesh" / "passage.cgns"));
  EXPECT_TRUE(q.valid);
  EXPECT_NEAR(q.Q, after, 1e-6);
  EXPECT_GT(after, before);  // the first pass's nodes at least
}
