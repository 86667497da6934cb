#include "passageMesh/workflow/MeshingOptimizationFiles.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/optimize/HistoryFiles.hpp"

namespace passageMesh {

namespace {

std::string fileContents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  if (!in) throw std::runtime_error(file.string() + ": cannot read file");
  return content.str();
}

}  // namespace

MeshingOptimizationFiles writeMeshingOptimizationFiles(const std::filesystem::path& caseDir,
                                                       const MeshingOptimization& run,
                                                       const std::string& gnuplot) {
  namespace fs = std::filesystem;
  const fs::path meshDict = fs::path("system") / "meshDict.xml";
  const fs::path original = fs::path("system") / "meshDict.xml.orig";
  const fs::path history = fs::path("postProcessing") / "iterOptimize" / "history.csv";
  const fs::path plot = fs::path("postProcessing") / "iterOptimize" / "convergence.png";

  MeshingOptimizationFiles report;
  if (run.result.history.empty()) {
    report.warnings.push_back("nothing was evaluated: no files written");
    return report;
  }
  std::vector<std::pair<fs::path, std::string>> files;
  if (run.foundValidMesh()) {
    // The user's own meshDict.xml is kept once; a later run must not replace it by an
    // earlier run's result. Without one there is nothing to keep: the defaults were used.
    if (fs::exists(caseDir / meshDict) && !fs::exists(caseDir / original))
      files.emplace_back(original, fileContents(caseDir / meshDict));
    files.emplace_back(meshDict, meshDictXml(run.best));
  } else {
    report.warnings.push_back("no valid mesh found: system/meshDict.xml left as it was");
  }
  files.emplace_back(history, historyCsv(run.box, run.result.history));

  std::vector<std::pair<fs::path, std::string>> targets;
  for (const auto& [file, content] : files) targets.emplace_back(caseDir / file, content);
  writeFilesAtomically(targets);
  for (const auto& entry : files) report.written.push_back(entry.first);

  try {
    plotConvergence(caseDir / history, caseDir / plot, gnuplot);
    report.written.push_back(plot);
  } catch (const std::runtime_error& e) {
    // An earlier run's plot would not match the new history.
    std::error_code ignored;
    fs::remove(caseDir / plot, ignored);
    report.warnings.push_back(e.what());
  }
  return report;
}

}  // namespace passageMesh
