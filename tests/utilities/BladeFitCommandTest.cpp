// bladeFit as a user runs it: good points give the two result files, bad input gives a
// one-line error naming the file, a non-zero exit, and leaves the case as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "../blade/BladeTestData.hpp"
#include "UtilityTestSupport.hpp"
#include "passageMesh/blade/BladeParametersFile.hpp"
#include "passageMesh/blade/BladeShape.hpp"

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
  const RunResult r = runTool(bladeFit, dir);
  EXPECT_NE(r.exitCode, 0) << name;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << name << ": " << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << name << ": " << r.err;
  EXPECT_EQ(readText(dir / "constant" / "bladeParameters.xml"), "sentinel") << name;
  EXPECT_FALSE(std::filesystem::exists(dir / "constant" / "bladeProfile.dat")) << name;
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
  const std::string profile = readText(dir / "constant" / "bladeProfile.dat");
  EXPECT_GE(std::count(profile.begin(), profile.end(), '\n'), 2000);
}

TEST(BladeFitCommand, HelpAndVersionExitZero) {
  const auto dir = freshCase("bladeFit_help");
  EXPECT_EQ(runTool(bladeFit, dir, "-help").exitCode, 0);
  EXPECT_EQ(runTool(bladeFit, dir, "--version").exitCode, 0);
  EXPECT_NE(runTool(bladeFit, dir, "-nonsense").exitCode, 0);
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
