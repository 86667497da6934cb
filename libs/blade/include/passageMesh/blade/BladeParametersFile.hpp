#pragma once
// constant/bladeParameters.xml: the blade shape parameters, the edges, and bladeFit's fit
// report (format: docs/case-format.md).
#include <filesystem>
#include <optional>
#include <string>

#include "passageMesh/blade/BladeParameters.hpp"

namespace passageMesh {

struct BladeFitReport {
  std::string pointsFile;  // the fitted points, as given to bladeFit
  int points = 0;
  double meanDeviation = 0;  // [m]
  double maxDeviation = 0;   // [m]
  int maxDeviationLine = 0;  // line in pointsFile of the worst point
  int iterations = 0;
  int starts = 0;
  double seconds = 0;
};

void writeBladeParametersFile(const std::filesystem::path& file, const BladeParameters& p,
                              const std::optional<BladeFitReport>& report);
// The file's content, for writing it together with other files (writeFilesAtomically).
std::string bladeParametersXml(const BladeParameters& p,
                               const std::optional<BladeFitReport>& report);

// Reads the shape section; throws InputError (file, line, what) for missing, unknown or
// non-finite entries.
BladeParameters readBladeParametersFile(const std::filesystem::path& file);

}  // namespace passageMesh
