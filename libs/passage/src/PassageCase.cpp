#include "passageMesh/passage/PassageCase.hpp"

#include <iostream>
#include <vector>

#include "passageMesh/blade/BladeParametersFile.hpp"

namespace passageMesh {

PassageCase readPassageCase(const std::filesystem::path& dir, const std::string& tool) {
  BladeShape blade(readBladeParametersFile(dir / "constant" / "bladeParameters.xml"));
  const double chord = blade.parameters().chord;
  std::vector<std::string> warnings;
  PassageCondition condition = readPassageDict(dir / "system" / "passageDict.xml", blade, &warnings);
  MeshingParameters parameters = readMeshDict(dir / "system" / "meshDict.xml", chord, &warnings);
  for (const auto& w : warnings) std::cerr << tool << ": warning: " << w << "\n";
  return {std::move(blade), condition, parameters};
}

}  // namespace passageMesh
