#pragma once
// What every meshing tool reads from a case: the fitted blade, the condition and the
// meshing parameters (docs/case-format.md). Warnings (values outside the method's range,
// clipped parameters) are printed to stderr as "TOOL: warning: ...".
#include <filesystem>
#include <string>

#include "passageMesh/blade/BladeShape.hpp"
#include "passageMesh/passage/MeshingParameters.hpp"
#include "passageMesh/passage/PassageCondition.hpp"

namespace passageMesh {

struct PassageCase {
  BladeShape blade;
  PassageCondition condition;
  MeshingParameters parameters;
};

// constant/bladeParameters.xml, system/passageDict.xml, system/meshDict.xml (optional).
PassageCase readPassageCase(const std::filesystem::path& caseDir, const std::string& tool);

}  // namespace passageMesh
