#include <gtest/gtest.h>

#include <fstream>
#include <iomanip>
#include <sstream>
#include <utility>

#include "../TestFiles.hpp"
#include "../blade/BladeTestData.hpp"

#include "passageMesh/core/InputError.hpp"
#include "passageMesh/passage/MeshingParameters.hpp"
#include "passageMesh/passage/PassageBoundary.hpp"
#include "passageMesh/passage/PassageCondition.hpp"

using namespace passageMesh;

namespace {
std::filesystem::path writeTemp(const std::string& name, const std::string& content) {
  return testData::writeTempFile("passageMeshPassageDictTest", name, content);
}
}  // namespace

TEST(PassageDict, ReadsLengthsInChordsAndWarnsOutsideTheMethodRange) {
  const auto file = writeTemp("a.xml",
                              "<passageDict><pitch>0.85c</pitch><xIn>0.5c</xIn><xOut>0.02</xOut>"
                              "<nO>60000</nO><firstCellHeight>1.1e-4c</firstCellHeight></passageDict>");
  std::vector<std::string> warnings;
  const PassageCondition c = readPassageDict(file, 0.1, &warnings);
  EXPECT_DOUBLE_EQ(c.pitch, 0.085);
  EXPECT_DOUBLE_EQ(c.xOut, 0.02);
  EXPECT_EQ(c.nO, 60000);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("<nO>"), std::string::npos) << warnings[0];
}

TEST(PassageDict, AWarningAboutALengthGivenInMetresSaysItInChords) {
  const auto file = writeTemp("m.xml",
                              "<passageDict><pitch>0.12</pitch><xIn>0.5c</xIn><xOut>0.5c</xOut>"
                              "<nO>30000</nO><firstCellHeight>1.1e-4c</firstCellHeight></passageDict>");
  std::vector<std::string> warnings;
  readPassageDict(file, 0.1, &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("<pitch> 0.12 (1.2c) is outside the method's range 0.3c..1c"),
            std::string::npos)
      << warnings[0];
}

TEST(PassageDict, RefusesImpossibleValuesAndMissingKeys) {
  auto dict = [](const std::string& pitch, const std::string& nO) {
    return "<passageDict>\n<pitch>" + pitch + "</pitch>\n<xIn>0.5c</xIn>\n<xOut>0.5c</xOut>\n<nO>" +
           nO + "</nO>\n<firstCellHeight>1e-5</firstCellHeight>\n</passageDict>";
  };
  try {
    readPassageDict(writeTemp("b.xml", dict("-0.1", "30000")), 0.1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("b.xml:2: <pitch> -0.1: expected a positive length"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(readPassageDict(writeTemp("c.xml", dict("0.1", "99")), 0.1), InputError);
  EXPECT_THROW(readPassageDict(writeTemp("d.xml", "<passageDict><pitch>1</pitch></passageDict>"), 0.1),
               InputError);
}

TEST(MeshDict, MissingFileGivesDefaultsAndOutOfRangeIsClippedWithAWarning) {
  const auto none = std::filesystem::temp_directory_path() / "passageMeshNoSuchMeshDict.xml";
  EXPECT_EQ(readMeshDict(none, 0.1).toArray(), MeshingParameters::defaults(0.1).toArray());
  // The struct's initialisers mirror etc/meshDictDefaults.xml for a chord of 1 m.
  EXPECT_EQ(MeshingParameters().toArray(), MeshingParameters::defaults(1.0).toArray());
  std::vector<std::string> warnings;
  const auto p = readMeshDict(
      writeTemp("m.xml", "<meshDict><betaIn>0.95</betaIn><yIn>0.2c</yIn><nT>400</nT></meshDict>"), 0.1,
      &warnings);
  EXPECT_DOUBLE_EQ(p.betaIn, 0.9);
  EXPECT_DOUBLE_EQ(p.yIn, 0.02);
  EXPECT_EQ(p.nT, 400);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("betaIn"), std::string::npos);
  EXPECT_THROW(readMeshDict(writeTemp("n.xml", "<meshDict><beta>1</beta></meshDict>"), 0.1), InputError);
  // A meshDict written before the splits existed reads with them at 0 (the method's outer
  // loop); a split beyond half a pitch is clipped with a warning.
  EXPECT_EQ(p.splitIn, 0.0);
  EXPECT_EQ(p.splitOut, 0.0);
  warnings.clear();
  EXPECT_DOUBLE_EQ(readMeshDict(writeTemp("s.xml", "<meshDict><splitOut>-0.7</splitOut></meshDict>"), 0.1, &warnings).splitOut, -0.5);
  EXPECT_EQ(warnings.size(), 1u);
}

// An integer beyond int's range is clipped as written, with a warning that shows it (it
// used to wrap around modulo 2^32: 4294967668 became 372, silently).
TEST(MeshDict, AnIntegerBeyondIntsRangeIsClippedAsWritten) {
  for (const auto& [written, clipped] : {std::pair<std::string, int>{"4294967668", 1000},
                                         {"-4294966924", 100}, {"99999999999999", 1000}}) {
    std::vector<std::string> warnings;
    const auto p = readMeshDict(writeTemp("big.xml", "<meshDict><nT>" + written + "</nT></meshDict>"), 0.1, &warnings);
    EXPECT_EQ(p.nT, clipped) << written;
    ASSERT_EQ(warnings.size(), 1u) << written;
    EXPECT_NE(warnings[0].find("<nT> " + written + " is outside [100, 1000], clipped to " +
                               std::to_string(clipped)), std::string::npos) << warnings[0];
  }
}

TEST(MeshDict, WritesAndReadsBack) {
  MeshingParameters p;
  p.yIn = -0.0123;
  p.nT = 517;
  p.gammaTe = 2.5;
  p.splitOut = -0.25;
  const auto file = writeTemp("w.xml", "");
  writeMeshDict(file, p);
  EXPECT_EQ(readMeshDict(file, 0.1).toArray(), p.toArray());
}

TEST(PassageDict, RefusesAPitchAtWhichTheBladeOverlapsItsNeighbour) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double extent = widestYExtent(blade).extent;
  auto dict = [](double pitch) {
    std::ostringstream text;
    text << std::setprecision(17) << pitch;
    return "<passageDict>\n<xIn>0.5c</xIn>\n<pitch>" + text.str() +
           "</pitch>\n<xOut>0.5c</xOut>\n<nO>30000</nO>\n<firstCellHeight>1e-5</firstCellHeight>\n</passageDict>";
  };
  const auto tight = writeTemp("overlap.xml", dict(0.98 * extent));
  try {
    readPassageDict(tight, blade);
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(tight.string() + ":3:"), std::string::npos) << what;  // the file and the pitch's line
    EXPECT_NE(what.find("overlaps its periodic neighbour"), std::string::npos) << what;
  }
  // The chord-only reader has no blade to check against.
  EXPECT_NO_THROW(readPassageDict(tight, blade.parameters().chord));
  // A pitch above the extent passes.
  EXPECT_EQ(readPassageDict(writeTemp("clear.xml", dict(1.02 * extent)), blade).pitch, 1.02 * extent);
}
