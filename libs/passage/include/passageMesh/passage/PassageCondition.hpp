#pragma once
// The passage condition (method.md section 1): what the user has and the policy's state.
// All lengths in metres. Read from system/passageDict.xml (docs/case-format.md).
#include <filesystem>
#include <string>
#include <vector>

namespace passageMesh {

class BladeShape;

struct PassageCondition {
  double pitch = 0;            // blade spacing
  double xIn = 0;              // inlet distance upstream of the leading edge
  double xOut = 0;             // outlet distance downstream of the trailing edge
  int nO = 0;                  // nodes in the O-block (nT * nN)
  double firstCellHeight = 0;  // first cell height normal to the blade
};

// The method's range of each condition value (method.md section 1), lengths in chords:
// outside it readPassageDict warns, and the sampler (PassageSampler.hpp) draws inside it.
struct PassageConditionRange {
  static constexpr double pitchMin = 0.3, pitchMax = 1.0;
  static constexpr double xInMin = 0.0, xInMax = 1.0;
  static constexpr double xOutMin = 0.0, xOutMax = 1.0;
  static constexpr int nOMin = 10000, nOMax = 50000;
  static constexpr double firstCellHeightMin = 2e-5, firstCellHeightMax = 2e-4;
};

// Reads system/passageDict.xml; lengths may be given in chords ("0.5c"). Values that no
// mesh can have (pitch <= 0, negative distances, nO < 100, firstCellHeight <= 0) are an
// InputError naming file and line. Values outside the method's range (method.md section 1:
// pitch 0.3..1 C, xIn and xOut 0..1 C, nO 10000..50000, firstCellHeight 2e-5..2e-4 C)
// are used but reported in `warnings`: the policy was not trained there.
PassageCondition readPassageDict(const std::filesystem::path& file, double chord,
                                 std::vector<std::string>* warnings = nullptr);
// As above for `blade` (its chord), and a pitch at or below the blade's widest extent in y
// (widestYExtent, PassageBoundary.hpp) is an InputError too: at that pitch the blade would
// overlap its periodic neighbour, so no passage exists.
PassageCondition readPassageDict(const std::filesystem::path& file, const BladeShape& blade,
                                 std::vector<std::string>* warnings = nullptr);

}  // namespace passageMesh
