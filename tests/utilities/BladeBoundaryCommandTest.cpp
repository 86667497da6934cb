// bladeBoundary as a user runs it: the boundary file for a good case, clear errors (and no
// file) for bad dictionaries, a warning for a clipped meshing parameter.
#include <gtest/gtest.h>

#include <cmath>

#include "../blade/BladeTestData.hpp"
#include "UtilityTestSupport.hpp"
#include "passageMesh/blade/BladeParametersFile.hpp"
#include "passageMesh/core/PointFile.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;

namespace {

const std::string bladeBoundary = BLADEBOUNDARY_EXECUTABLE;

std::filesystem::path caseWith(const std::string& name, const std::string& passageDict,
                               const std::string& meshDict = "") {
  const auto dir = freshCase("bladeBoundary_" + name);
  writeBladeParametersFile(dir / "constant" / "bladeParameters.xml", typicalTurbineBlade(), {});
  writeText(dir / "system" / "passageDict.xml", passageDict);
  if (!meshDict.empty()) writeText(dir / "system" / "meshDict.xml", meshDict);
  return dir;
}

std::string passageDict(const std::string& pitch) {
  return "<passageDict>\n<pitch>" + pitch +
         "</pitch>\n<xIn>0.5c</xIn>\n<xOut>0.5c</xOut>\n<nO>30000</nO>\n"
         "<firstCellHeight>1.1e-4c</firstCellHeight>\n</passageDict>\n";
}

}  // namespace

TEST(BladeBoundaryCommand, WritesPeriodicBoundaries) {
  const auto dir = caseWith("good", passageDict("0.85c"), "<meshDict><betaIn>2</betaIn></meshDict>");
  const RunResult r = runTool(bladeBoundary, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("warning"), std::string::npos);  // betaIn clipped to 0.9
  EXPECT_NE(r.err.find("betaIn"), std::string::npos);
  // Blocks 0 and 1 (lower, upper) are the first 383 points each; upper = lower + pitch.
  const auto points = readPointFile(dir / "constant" / "passageBoundary.dat").points;
  const double pitch = 0.85 * typicalTurbineBlade().chord;
  ASSERT_GT(points.size(), 2u * 383u);
  for (int k = 0; k < 383; ++k) {
    ASSERT_TRUE(std::isfinite(points[k].y()));
    EXPECT_EQ(points[383 + k].x(), points[k].x());
    EXPECT_NEAR(points[383 + k].y() - points[k].y(), pitch, 1e-15);
  }
}

TEST(BladeBoundaryCommand, RefusesBadInput) {
  const auto negative = caseWith("negativePitch", passageDict("-0.01"));
  RunResult r = runTool(bladeBoundary, negative);
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("passageDict.xml:2: <pitch> -0.01: expected a positive length"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(negative / "constant" / "passageBoundary.dat"));

  const auto noBlade = freshCase("bladeBoundary_noBlade");
  writeText(noBlade / "system" / "passageDict.xml", passageDict("0.85c"));
  r = runTool(bladeBoundary, noBlade);
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("bladeParameters.xml: file not found"), std::string::npos) << r.err;
}
