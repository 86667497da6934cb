#include "passageMesh/blade/BladeParametersFile.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "../TestFiles.hpp"
#include "BladeTestData.hpp"
#include "passageMesh/core/InputError.hpp"

using namespace passageMesh;

TEST(BladeParametersFile, RoundTripsExactly) {
  const auto file = testData::tempFolder("bladeParametersFile") / "good.xml";
  const BladeParameters p = testData::typicalTurbineBlade();
  BladeFitReport report;
  report.points = 123;
  report.meanDeviation = 1.5e-5;
  std::filesystem::create_directories(file.parent_path());
  writeBladeParametersFile(file, p, report);
  EXPECT_EQ(readBladeParametersFile(file).toArray(), p.toArray());
}

TEST(BladeParametersFile, MissingOrBadEntriesAreErrors) {
  const auto file = testData::writeTempFile(
      "bladeParametersFile", "bad.xml", "<bladeParameters><shape><xLe>0</xLe></shape></bladeParameters>");
  EXPECT_THROW(readBladeParametersFile(file), InputError);
  std::ofstream(file) << "<bladeParameters><chord>1</chord></bladeParameters>";
  EXPECT_THROW(readBladeParametersFile(file), InputError);
  // A complete but invalid shape (zero camber handle) is refused, naming the reason.
  BladeParameters p = testData::typicalTurbineBlade();
  p.distLe = 0;
  writeBladeParametersFile(file, p, {});
  try {
    readBladeParametersFile(file);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a valid blade"), std::string::npos) << e.what();
  }
}
