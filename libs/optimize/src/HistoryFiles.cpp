#include "passageMesh/optimize/HistoryFiles.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "passageMesh/core/AtomicFile.hpp"

namespace passageMesh {

namespace {

std::string formatValue(double v, bool integer) {
  return integer && std::isfinite(v) ? std::to_string(std::llround(v)) : formatExact(v);
}

// A path as a single-quoted word for the shell.
std::string shellQuoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// A path as a single-quoted gnuplot string (a quote is written twice).
std::string gnuplotQuoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

bool onPath(const std::string& program) {
  if (program.find('/') != std::string::npos) return ::access(program.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  return false;
}

std::string firstLine(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t^") != std::string::npos) return line;
  return "";
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
  namespace fs = std::filesystem;
  if (!onPath(gnuplot))
    throw std::runtime_error("cannot plot " + pngFile.string() + ": " + gnuplot +
                             " is not installed (Debian package gnuplot-nox)");
  // gnuplot writes a temporary beside the target, renamed when complete: a reader never
  // sees half a PNG. The last two columns of the CSV are the value and the best so far.
  const std::string tag = ".tmp" + std::to_string(static_cast<long>(::getpid()));
  const fs::path temporary = pngFile.string() + tag;
  const fs::path script = pngFile.string() + tag + ".gp";
  const fs::path errors = pngFile.string() + tag + ".err";
  std::error_code ignored;
  if (pngFile.has_parent_path()) fs::create_directories(pngFile.parent_path(), ignored);
  const std::string csv = gnuplotQuoted(csvFile.string());
  writeFileAtomically(script,
                      "set terminal pngcairo size 900,600\n"
                      "set output " + gnuplotQuoted(temporary.string()) + "\n"
                      "set datafile separator ','\n"
                      "stats " + csv + " skip 1 nooutput\n"
                      "n = STATS_columns\n"
                      "set xlabel 'evaluation'\nset ylabel 'value'\nset grid\nset key bottom right\n"
                      "plot " + csv + " skip 1 using 1:n-1 with points pt 7 ps 0.4 title 'value', "
                      "'' skip 1 using 1:n with lines lw 2 title 'best so far'\n");
  const int status = std::system((shellQuoted(gnuplot) + " " + shellQuoted(script.string()) + " 2>" +
                                  shellQuoted(errors.string())).c_str());
  const std::string why = firstLine(errors);
  fs::remove(script, ignored);
  fs::remove(errors, ignored);
  const bool drawn = status == 0 && fs::exists(temporary);
  std::error_code renamed;
  if (drawn) fs::rename(temporary, pngFile, renamed);
  if (!drawn || renamed) {
    fs::remove(temporary, ignored);
    throw std::runtime_error("cannot plot " + pngFile.string() + ": gnuplot failed" +
                             (why.empty() ? std::string() : " (" + why + ")"));
  }
}

}  // namespace passageMesh
