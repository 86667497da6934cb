#pragma once
// The optimisation history on disk: a CSV table (one row per evaluation) and a
// convergence plot drawn by gnuplot from it, like OpenFOAM's foamMonitor: every value and
// the best so far against the evaluation.
#include <filesystem>
#include <string>

#include "passageMesh/optimize/BoxProblem.hpp"
#include "passageMesh/optimize/OptimizationHistory.hpp"

namespace passageMesh {

// "evaluation,<names>,<valueName>,best<valueName>" then one row per evaluation; values
// with 17 significant digits (read back exactly), integer dimensions as integers.
std::string historyCsv(const BoxProblem& problem, const OptimizationHistory& history,
                       const std::string& valueName = "Q");
// Written atomically (temporary + rename).
void writeHistoryCsv(const std::filesystem::path& file, const BoxProblem& problem,
                     const OptimizationHistory& history, const std::string& valueName = "Q");

// Plots the value and the best so far against the evaluation from a history CSV into a
// PNG (written atomically). Throws std::runtime_error with a one-line message when gnuplot
// is not on the PATH or fails; `gnuplot` names the program (tests point it elsewhere).
void plotConvergence(const std::filesystem::path& csvFile, const std::filesystem::path& pngFile,
                     const std::string& gnuplot = "gnuplot");

}  // namespace passageMesh
