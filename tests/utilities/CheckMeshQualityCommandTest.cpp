// checkMeshQuality as a user runs it: the report and the VTK fields for a valid mesh, the
// invalid-mesh value and exit code 2 for a folded one, a one-line error (and no output)
// for a missing mesh.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include "../quality/QualityTestData.hpp"
#include "UtilityTestSupport.hpp"
#include "passageMesh/quality/MeshQuality.hpp"
#include "passageMesh/structured/CgnsWriter.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;

namespace {

const std::string checkMeshQuality = CHECKMESHQUALITY_EXECUTABLE;

std::filesystem::path caseWithMesh(const std::string& name, const StructuredMesh& mesh) {
  const auto dir = freshCase("checkMeshQuality_" + name);
  writeCgns(mesh, dir / "mesh" / "passage.cgns");
  return dir;
}

double childValue(const tinyxml2::XMLElement* root, const char* name) {
  const tinyxml2::XMLElement* e = root->FirstChildElement(name);
  return e ? std::stod(e->GetText()) : std::nan("");
}

}  // namespace

TEST(CheckMeshQualityCommand, ReportsQualityAndAddsCellFields) {
  const HohMesh hoh = validHohMesh();
  ASSERT_TRUE(hoh.valid) << hoh.problem;
  const MeshQuality expected = computeMeshQuality(hoh.mesh);
  const auto dir = caseWithMesh("valid", hoh.mesh);
  const RunResult r = runTool(checkMeshQuality, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("(valid)"), std::string::npos) << r.out;

  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.LoadFile((dir / "postProcessing" / "meshQuality.xml").c_str()), tinyxml2::XML_SUCCESS);
  const tinyxml2::XMLElement* root = doc.RootElement();
  ASSERT_NE(root, nullptr);
  EXPECT_STREQ(root->Attribute("valid"), "true");
  // 17 digits: the values read back are the library's, bit for bit.
  EXPECT_EQ(childValue(root, "Q"), expected.Q);
  EXPECT_EQ(childValue(root, "QJmin"), expected.QJmin);
  EXPECT_EQ(childValue(root, "QJavg"), expected.QJavg);
  EXPECT_EQ(childValue(root, "QSmin"), expected.QSmin);
  EXPECT_EQ(childValue(root, "QSavg"), expected.QSavg);
  const tinyxml2::XMLElement* worst = root->FirstChildElement("worstQS");
  ASSERT_NE(worst, nullptr);
  EXPECT_STREQ(worst->Attribute("block"), "OBlock");
  EXPECT_EQ(worst->IntAttribute("i"), expected.worstQS.i);
  EXPECT_EQ(worst->IntAttribute("j"), expected.worstQS.j);

  const std::string vts = readText(dir / "mesh" / "passage" / "OBlock.vts");
  EXPECT_NE(vts.find("Name=\"QJ\""), std::string::npos);
  EXPECT_NE(vts.find("Name=\"QS\""), std::string::npos);
  EXPECT_NE(readText(dir / "mesh" / "passage.vtm").find("passage/OBlock.vts"), std::string::npos);
}

TEST(CheckMeshQualityCommand, FoldedMeshIsReportedInvalid) {
  HohMesh hoh = validHohMesh();
  StructuredBlock& o = hoh.mesh.blocks[1];
  // Node (50, 10) pushed past node (50, 11).
  o.xAt(50, 10) = 2 * o.xAt(50, 11) - o.xAt(50, 10);
  o.yAt(50, 10) = 2 * o.yAt(50, 11) - o.yAt(50, 10);
  const auto dir = caseWithMesh("folded", hoh.mesh);
  const RunResult r = runTool(checkMeshQuality, dir);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("INVALID MESH"), std::string::npos) << r.err;
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.LoadFile((dir / "postProcessing" / "meshQuality.xml").c_str()), tinyxml2::XML_SUCCESS);
  EXPECT_STREQ(doc.RootElement()->Attribute("valid"), "false");
  EXPECT_EQ(childValue(doc.RootElement(), "Q"), invalidMeshQuality);
}

TEST(CheckMeshQualityCommand, MissingMeshIsAnErrorAndWritesNothing) {
  const auto dir = freshCase("checkMeshQuality_noMesh");
  const RunResult r = runTool(checkMeshQuality, dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("checkMeshQuality: error: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("passage.cgns: file not found"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "postProcessing" / "meshQuality.xml"));
}
