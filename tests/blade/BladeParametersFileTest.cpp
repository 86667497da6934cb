#include "passageMesh/blade/BladeParametersFile.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "BladeTestData.hpp"
#include "passageMesh/core/InputError.hpp"

using namespace passageMesh;

TEST(BladeParametersFile, RoundTripsExactly) {
  const auto file = std::filesystem::temp_directory_path() / "passageMeshBladeParameters.xml";
  const BladeParameters p = testData::typicalTurbineBlade();
  BladeFitReport report;
  report.points = 123;
  report.meanDeviation = 1.5e-5;
  writeBladeParametersFile(file, p, report);
  EXPECT_EQ(readBladeParametersFile(file).toArray(), p.toArray());
}

TEST(BladeParametersFile, MissingOrBadEntriesAreErrors) {
  const auto file = std::filesystem::temp_directory_path() / "passageMeshBadBladeParameters.xml";
  std::ofstream(file) << "<bladeParameters><shape><xLe>0</xLe></shape></bladeParameters>";
  EXPECT_THROW(readBladeParametersFile(file), InputError);
  std::ofstream(file) << "<bladeParameters><chord>1</chord></bladeParameters>";
  EXPECT_THROW(readBladeParametersFile(file), InputError);
}
