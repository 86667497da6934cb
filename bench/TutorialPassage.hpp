#pragma once
// A tutorial's passage as the benches use it: its blade points fitted (bladeFit's
// defaults) and its system/passageDict.xml condition. The tutorials are the four of the
// paper, in tutorials/ of this source tree.
#include <array>
#include <filesystem>
#include <string>

#include "passageMesh/blade/BladeFit.hpp"
#include "passageMesh/blade/BladePoints.hpp"
#include "passageMesh/core/PointFile.hpp"
#include "passageMesh/passage/PassageCondition.hpp"

namespace passageMesh::bench {

inline const std::array<std::string, 4>& tutorialNames() {
  static const std::array<std::string, 4> names{"LS89", "STD10", "T106A", "SIRT"};
  return names;
}

struct TutorialPassage {
  std::string name;
  BladeParameters blade;
  PassageCondition condition;
};

inline TutorialPassage loadTutorialPassage(const std::string& name) {
  const auto dir = std::filesystem::path(PASSAGEMESH_SOURCE_DIR) / "tutorials" / name;
  const auto points = orderBladePoints(readPointFile(dir / "constant" / "bladePoints.dat")).points;
  TutorialPassage t{name, fitBlade(points).parameters, {}};
  t.condition = readPassageDict(dir / "system" / "passageDict.xml", t.blade.chord);
  return t;
}

}  // namespace passageMesh::bench
