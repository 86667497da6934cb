#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "../TestFiles.hpp"

#include "passageMesh/optimize/HistoryFiles.hpp"
#include "passageMesh/optimize/Optimizer.hpp"
#include "passageMesh/optimize/SyntheticObjectives.hpp"

using namespace passageMesh;

namespace {

OptimizationResult shortRun(const SyntheticProblem& problem) {
  OptimizerOptions options;
  options.budget = 60;
  return optimize(problem.box, evaluateInParallel(problem.objective, 1), options);
}

// `plot` must throw a std::runtime_error whose message is one line containing `expected`.
template <typename Plot>
void expectOneLineError(const Plot& plot, const std::string& expected) {
  try {
    plot();
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(expected), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

}  // namespace

TEST(HistoryFiles, CsvHasOneRowPerEvaluationThatReadsBackExactly) {
  const SyntheticProblem problem = twoPeaksWithInvalidRegion();
  const auto r = shortRun(problem);
  const auto file = testData::tempFolder("optimize") / "history.csv";
  writeHistoryCsv(file, problem.box, r.history);
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "evaluation,yIn,yOut,alphaCamber,betaIn,betaOut,nT,gammaLE,gammaTE,Q,bestQ");
  long rows = 0;
  for (; std::getline(in, line); ++rows) {
    std::stringstream row(line);
    std::string cell;
    std::vector<std::string> cells;
    while (std::getline(row, cell, ',')) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 11u) << line;
    const Evaluation& e = r.history[rows];
    EXPECT_EQ(std::stol(cells[0]), e.index);
    EXPECT_EQ(cells[6].find('.'), std::string::npos) << "nT as an integer: " << cells[6];
    for (int k = 0; k < 8; ++k) EXPECT_EQ(std::stod(cells[1 + k]), e.point[k]);
    EXPECT_EQ(std::stod(cells[9]), e.value);
    EXPECT_EQ(std::stod(cells[10]), e.bestSoFar);
  }
  EXPECT_EQ(rows, 60);
}

TEST(HistoryFiles, ConvergencePlotIsAPng) {
  const SyntheticProblem problem = shiftedBowl();
  const auto folder = testData::tempFolder("optimize");
  writeHistoryCsv(folder / "plotted.csv", problem.box, shortRun(problem).history);
  const auto png = folder / "convergence.png";
  plotConvergence(folder / "plotted.csv", png);
  std::ifstream in(png, std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << "left over: " << entry.path();
}

TEST(HistoryFiles, PlotWithoutGnuplotIsAOneLineError) {
  const auto folder = testData::tempFolder("optimize");
  expectOneLineError([&] { plotConvergence(folder / "any.csv", folder / "none.png", "noSuchGnuplotProgram"); },
                     "noSuchGnuplotProgram is not installed");
  EXPECT_FALSE(std::filesystem::exists(folder / "none.png"));
}

TEST(HistoryFiles, FailingGnuplotIsAOneLineErrorNamingTheCause) {
  const auto folder = testData::tempFolder("optimize");
  expectOneLineError([&] { plotConvergence(folder / "missing.csv", folder / "failed.png"); }, "gnuplot failed");
  EXPECT_FALSE(std::filesystem::exists(folder / "failed.png"));
}
