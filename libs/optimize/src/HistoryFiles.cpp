#include "passageMesh/optimize/HistoryFiles.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/GnuplotRun.hpp"
#include "passageMesh/core/NumberFormat.hpp"

namespace passageMesh {

namespace {

std::string formatValue(double v, bool integer) {
  return integer && std::isfinite(v) ? std::to_string(std::llround(v)) : formatExact(v);
}

}  // namespace

std::string historyCsv(const BoxProblem& problem, const OptimizationHistory& history,
                       const std::string& valueName) {
  std::ostringstream out;
  out << "evaluation";
  for (int k = 0; k < problem.dimension(); ++k) out << ',' << problem.name(k);
  out << ',' << valueName << ",best" << valueName << '\n';
  for (const Evaluation& e : history) {
    out << e.index;
    for (int k = 0; k < problem.dimension(); ++k) out << ',' << formatValue(e.point[k], problem.isInteger(k));
    out << ',' << formatExact(e.value) << ',' << formatExact(e.bestSoFar) << '\n';
  }
  return out.str();
}

void writeHistoryCsv(const std::filesystem::path& file, const BoxProblem& problem,
                     const OptimizationHistory& history, const std::string& valueName) {
  writeFileAtomically(file, historyCsv(problem, history, valueName));
}

void plotConvergence(const std::filesystem::path& csvFile, const std::filesystem::path& pngFile,
                     const std::string& gnuplot) {
  try {
    GnuplotRun plot(gnuplot);
    // The last two columns of the CSV are the value and the best so far.
    const std::string csv = gnuplotQuoted(csvFile.string());
    plot.run(gnuplotPngTerminal(900, 600) + plot.output(pngFile) +
             "set datafile separator ','\n"
             "stats " + csv + " skip 1 nooutput\n"
             "n = STATS_columns\n"
             "set xlabel 'evaluation'\nset ylabel 'value'\nset grid\nset key bottom right\n"
             "plot " + csv + " skip 1 using 1:n-1 with points pt 7 ps 0.4 title 'value', "
             "'' skip 1 using 1:n with lines lw 2 title 'best so far'\n");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("cannot plot " + pngFile.string() + ": " + e.what());
  }
}

}  // namespace passageMesh
