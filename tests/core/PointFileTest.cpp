#include "passageMesh/core/PointFile.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "../TestFiles.hpp"

#include "passageMesh/core/InputError.hpp"

using namespace passageMesh;

namespace {
std::filesystem::path writeTemp(const std::string& name, const std::string& content) {
  return testData::writeTempFile("passageMeshPointFileTest", name, content);
}

std::string errorOf(const std::string& content) {
  try {
    readPointFile(writeTemp("bad.dat", content));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(PointFile, ReadsPointsCommentsAndLineNumbers) {
  const auto set = readPointFile(writeTemp("ok.dat", "# header\n\n1 2\n 3.5e-1\t-4 # note\n"));
  ASSERT_EQ(set.points.size(), 2u);
  EXPECT_EQ(set.points[1], Eigen::Vector2d(0.35, -4));
  EXPECT_EQ(set.lines[0], 3);
  EXPECT_EQ(set.lines[1], 4);
}

TEST(PointFile, AcceptsByteOrderMarkCarriageReturnsAndTabs) {
  const auto set = readPointFile(writeTemp("bom.dat", "\xEF\xBB\xBF" "1\t2\r\n3 4\r\n"));
  ASSERT_EQ(set.points.size(), 2u);
  EXPECT_EQ(set.points[0], Eigen::Vector2d(1, 2));
  EXPECT_EQ(set.points[1], Eigen::Vector2d(3, 4));
}

TEST(PointFile, BadContentNamesFileAndLine) {
  EXPECT_NE(errorOf("").find("no points"), std::string::npos);
  EXPECT_NE(errorOf("1 2\n3\n").find("bad.dat:2: expected two numbers"), std::string::npos);
  EXPECT_NE(errorOf("1 2\n3 nan\n").find("bad.dat:2"), std::string::npos);
  EXPECT_NE(errorOf("1 2\nx 4\n").find("'x'"), std::string::npos);
  EXPECT_NE(errorOf("1 2\n3 4 5\n").find("found 3"), std::string::npos);
  EXPECT_THROW(readPointFile("/nonexistent/points.dat"), InputError);
}

TEST(PointFile, FormatsExactly) {
  const std::vector<Eigen::Vector2d> p{{0.1, 1.0 / 3.0}};
  const auto file = writeTemp("round.dat", formatPointFile(p, {"a header"}));
  EXPECT_EQ(readPointFile(file).points[0], p[0]);
}
