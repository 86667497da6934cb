#pragma once
// What iterOptimize writes into the case (docs/case-format.md):
//   system/meshDict.xml                   the best parameters (when a valid mesh was found)
//   system/meshDict.xml.orig              the meshDict.xml the first run found, kept once:
//                                         never overwritten; none when there was none
//   postProcessing/iterOptimize/history.csv       every evaluation (HistoryFiles.hpp)
//   postProcessing/iterOptimize/convergence.png   Q and the best Q (gnuplot)
// The first three are written as one step (writeFilesAtomically): a reader, or a run cut
// short by a second Ctrl-C, sees the old or the new complete files. The plot comes after
// them; without gnuplot it is a warning, not a failure.
#include <filesystem>
#include <string>
#include <vector>

#include "passageMesh/workflow/MeshingOptimization.hpp"

namespace passageMesh {

struct MeshingOptimizationFiles {
  std::vector<std::filesystem::path> written;  // relative to the case directory
  std::vector<std::string> warnings;            // one line each (no plot; meshDict kept)
};

// `gnuplot` names the plotting program (tests point it elsewhere).
MeshingOptimizationFiles writeMeshingOptimizationFiles(const std::filesystem::path& caseDir,
                                                       const MeshingOptimization& run,
                                                       const std::string& gnuplot = "gnuplot");

}  // namespace passageMesh
