// bladeFit as a user runs it: good points give the two result files, bad input gives a
// one-line error naming the file, a non-zero exit, and leaves the case as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "../blade/BladeTestData.hpp"
#include "UtilityTestSupport.hpp"
#include "passageMesh/blade/BladeParametersFile.hpp"
#include "passageMesh/blade/BladeProjection.hpp"
#include "passageMesh/blade/BladeShape.hpp"
#include "passageMesh/core/PointFile.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;

namespace {

const std::string bladeFit = BLADEFIT_EXECUTABLE;

BladeParameters blade() { return typicalTurbineBlade(); }

std::string pointLines(std::vector<Eigen::Vector2d> points) {
  std::ostringstream s;
  s.precision(17);
  for (const auto& q : points) s << q.x() << " " << q.y() << "\n";
  return s.str();
}

// Runs bladeFit on a case whose bladePoints.dat holds `points` (nothing written when
// `points` is null) and whose results are pre-filled with a sentinel, then checks the
// failure: non-zero exit, one line on stderr containing `expected`, results untouched.
void expectRefused(const std::string& name, const char* points, const std::string& expected,
                   const std::string& dictionary = "") {
  const auto dir = freshCase("bladeFit_" + name);
  if (points) writeText(dir / "constant" / "bladePoints.dat", points);
  if (!dictionary.empty()) writeText(dir / "system" / "bladeFitDict.xml", dictionary);
  writeText(dir / "constant" / "bladeParameters.xml", "sentinel");
  writeText(dir / "constant" / "bladeProfile.dat", "sentinel");
  const RunResult r = runTool(bladeFit, dir);
  EXPECT_NE(r.exitCode, 0) << name;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << name << ": " << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << name << ": " << r.err;
  EXPECT_EQ(readText(dir / "constant" / "bladeParameters.xml"), "sentinel") << name;
  EXPECT_EQ(readText(dir / "constant" / "bladeProfile.dat"), "sentinel") << name;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "constant"))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
}

}  // namespace

TEST(BladeFitCommand, FitsPointsAndWritesBothFiles) {
  const auto dir = freshCase("bladeFit_good");
  auto loop = BladeShape(blade()).sampleLoop(300);
  std::reverse(loop.begin(), loop.end());                 // clockwise
  std::rotate(loop.begin(), loop.begin() + 77, loop.end());  // any start point
  loop.push_back(loop.front());                           // closed
  writeText(dir / "constant" / "bladePoints.dat", "# a test blade\n" + pointLines(loop));
  const RunResult r = runTool(bladeFit, dir, "-threads 1");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const BladeParameters fitted = readBladeParametersFile(dir / "constant" / "bladeParameters.xml");
  EXPECT_NEAR(fitted.chord, blade().chord, 1e-3 * blade().chord);
  // 2000 distinct points plus the first repeated: a closed loop.
  const auto profile = readPointFile(dir / "constant" / "bladeProfile.dat").points;
  ASSERT_EQ(profile.size(), 2001u);
  EXPECT_EQ(profile.front(), profile.back());
  EXPECT_LT(deviationFromProfile(BladeShape(blade()), profile).max, 1e-4 * blade().chord);
  const std::string xml = readText(dir / "constant" / "bladeParameters.xml");
  EXPECT_NE(xml.find("<points>300</points>"), std::string::npos);  // the closing repeat dropped
}

TEST(BladeFitCommand, CommandLine) {
  const auto dir = freshCase("bladeFit_help");
  RunResult r = runTool(bladeFit, dir, "-help");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("-case"), std::string::npos);
  r = runTool(bladeFit, dir, "--version");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("passageMesh"), std::string::npos);
  EXPECT_NE(runTool(bladeFit, dir, "-nonsense").exitCode, 0);
  // A stray word (a case name without -case) and abbreviations are refused.
  r = runTool(bladeFit, dir, "otherCase");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(runTool(bladeFit, dir, "-cas .").exitCode, 0);
  EXPECT_NE(runTool(bladeFit, dir, "-threads -1").exitCode, 0);
  r = runCommand(bladeFit, "-case /nonexistent/case", dir);
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("case directory not found"), std::string::npos) << r.err;
  r = runCommand(bladeFit, "-case '" + (dir / "stdout.txt").string() + "'", dir);  // (a file)
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("stdout.txt: not a directory (expected the case directory)"), std::string::npos) << r.err;
}

TEST(BladeFitCommand, AFailedWriteLeavesEveryResultAsItWas) {
  const auto dir = freshCase("bladeFit_unwritable");
  writeText(dir / "constant" / "bladePoints.dat", pointLines(BladeShape(blade()).sampleLoop(200)));
  writeText(dir / "constant" / "bladeProfile.dat", "sentinel");
  std::filesystem::create_directories(dir / "constant" / "bladeParameters.xml");  // cannot be replaced
  const RunResult r = runTool(bladeFit, dir, "-threads 1");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("bladeParameters.xml: cannot replace"), std::string::npos) << r.err;
  EXPECT_EQ(readText(dir / "constant" / "bladeProfile.dat"), "sentinel");
  for (const auto& entry : std::filesystem::directory_iterator(dir / "constant"))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST(BladeFitCommand, RefusesBadPointFiles) {
  const std::string good = pointLines(BladeShape(blade()).sampleLoop(60));
  expectRefused("missing", nullptr, "bladePoints.dat: file not found");
  expectRefused("empty", "", "bladePoints.dat: no points");
  expectRefused("oneColumn", "1.0\n2.0\n", "bladePoints.dat:1: expected two numbers");
  expectRefused("nan", (good + "0.1 nan\n").c_str(), "bladePoints.dat:61: expected a finite number");
  expectRefused("text", ("0.1 0.2x\n" + good).c_str(), "bladePoints.dat:1: expected a finite number");
  expectRefused("fewPoints", "0 0\n1 0\n1 1\n", "expected at least 20");
  // Line 31 repeats line 1.
  const auto points = BladeShape(blade()).sampleLoop(60);
  auto withDuplicate = points;
  withDuplicate.insert(withDuplicate.begin() + 30, points[0]);
  expectRefused("duplicate", pointLines(withDuplicate).c_str(),
                "bladePoints.dat:31: duplicate point (same as line 1)");
  // A figure-of-eight: the loop crosses itself.
  std::string eight;
  for (int k = 0; k < 40; ++k) {
    const double t = 2 * M_PI * (k + 0.5) / 40;  // no sample on the crossing itself
    eight += std::to_string(std::sin(t)) + " " + std::to_string(std::sin(t) * std::cos(t)) + "\n";
  }
  expectRefused("selfIntersecting", eight.c_str(), "intersects itself");
}

TEST(BladeFitCommand, RefusesBadDictionaries) {
  const std::string good = pointLines(BladeShape(blade()).sampleLoop(60));
  expectRefused("malformedXml", good.c_str(), "bladeFitDict.xml:1: malformed XML",
                "<bladeFitDict><maxRounds>2</bladeFitDict>");
  expectRefused("unknownKey", good.c_str(), "unknown key <maxRound>",
                "<bladeFitDict>\n<maxRound>2</maxRound>\n</bladeFitDict>");
  expectRefused("outOfRange", good.c_str(), "bladeFitDict.xml:2: <profilePoints> 10 is out of range",
                "<bladeFitDict>\n<profilePoints>10</profilePoints>\n</bladeFitDict>");
}
