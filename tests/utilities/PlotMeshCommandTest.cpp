// plotMesh as a user runs it: the pictures of a case's mesh; a missing mesh is one error
// line and no pictures.
#include <gtest/gtest.h>

#include "../quality/QualityTestData.hpp"
#include "UtilityTestSupport.hpp"
#include "passageMesh/structured/CgnsWriter.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;

namespace {
const std::string plotMeshTool = PLOTMESH_EXECUTABLE;
}

TEST(PlotMeshCommand, DrawsThePicturesWithoutBladeFiles) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot not installed";
  const auto dir = freshCase("plotMesh_mesh");
  writeCgns(validHohMesh().mesh, dir / "mesh" / "passage.cgns");
  const RunResult r = runTool(plotMeshTool, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("warning: no blade picture"), std::string::npos) << r.err;
  for (const char* f : {"passage", "leadingEdge", "trailingEdge", "qualityQS", "qualityQJ"})
    EXPECT_TRUE(std::filesystem::exists(dir / "postProcessing" / "plots" / (std::string(f) + ".png"))) << f;
}

TEST(PlotMeshCommand, MissingMeshIsAnErrorAndDrawsNothing) {
  const auto dir = freshCase("plotMesh_noMesh");
  const RunResult r = runTool(plotMeshTool, dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err.rfind("plotMesh: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("passage.cgns: file not found"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "postProcessing" / "plots"));
}
