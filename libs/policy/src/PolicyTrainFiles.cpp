#include "passageMesh/policy/PolicyTrainFiles.hpp"

#include <cstdio>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/GnuplotRun.hpp"

namespace passageMesh {

namespace fs = std::filesystem;

PolicyTrainPaths::PolicyTrainPaths(const fs::path& caseDir)
    : policy(caseDir / "policy" / "policy.xml"),
      finalPolicy(caseDir / "policy" / "final.xml"),
      checkpoint(caseDir / "policy" / "checkpoint.pt"),
      learningCsv(caseDir / "postProcessing" / "policyTrain" / "learning.csv"),
      validationCsv(caseDir / "postProcessing" / "policyTrain" / "validation.csv"),
      learningPng(caseDir / "postProcessing" / "policyTrain" / "learning.png") {}

namespace {

std::string line(const char* format, auto... values) {
  char text[256];
  std::snprintf(text, sizeof text, format, values...);
  return text;
}

void plotCurves(const PolicyTrainPaths& paths, std::optional<double> reference) {
  GnuplotRun plot;
  const std::string learning = gnuplotQuoted(paths.learningCsv.string());
  const std::string validation = gnuplotQuoted(paths.validationCsv.string());
  plot.run(gnuplotPngTerminal(1000, 600) + plot.output(paths.learningPng) +
           "set datafile separator ','\n"
           "set key bottom right\nset grid\n"
           "set xlabel 'episode'\nset ylabel 'reward (Q; -1 = invalid mesh)'\n"
           "set yrange [-1.05:1.05]\n"
           "set title 'policyTrain: learning curve'\n"
           "plot " + learning + " every ::1 using 1:2 with lines lw 2 title 'training: mean reward (with noise)', " +
           learning + " every ::1 using 1:3 with lines dt 2 title 'training: share of valid meshes', " +
           validation + " every ::1 using 1:2 with linespoints pt 7 title 'validation: mean reward (noise-free)', " +
           validation + " every ::1 using 1:3 with linespoints pt 5 title 'validation: median reward'" +
           (reference ? line(", %.17g with lines dt 3 lw 2 lc 'black' title 'validation: mean reward of the defaults'",
                             *reference)
                      : std::string()) +
           "\n");
}

}  // namespace

std::vector<fs::path> writeLearningCurves(const PolicyTrainPaths& paths, const PolicyTrainer& trainer,
                                          std::vector<std::string>* warnings, std::optional<double> reference) {
  std::string learning = "episode,meanReward,validFraction,criticLoss,sigma,seconds\n";
  for (const LearningRecord& r : trainer.learningCurve())
    learning += line("%ld,%.17g,%.17g,%.17g,%.17g,%.6f\n", r.episode, r.meanReward, r.validFraction,
                     r.criticLoss, r.sigma, r.seconds);
  std::string validation = "episode,meanReward,medianReward,valid,passages\n";
  for (const ValidationRecord& r : trainer.validationCurve())
    validation += line("%ld,%.17g,%.17g,%d,%d\n", r.episode, r.meanReward, r.medianReward, r.valid,
                       r.passages);
  writeFilesAtomically({{paths.learningCsv, learning}, {paths.validationCsv, validation}});
  std::vector<fs::path> written{paths.learningCsv, paths.validationCsv};
  if (trainer.learningCurve().empty()) return written;
  try {
    plotCurves(paths, reference);
    written.push_back(paths.learningPng);
  } catch (const std::exception& e) {
    if (warnings) warnings->push_back(std::string("no learning picture: ") + e.what());
  }
  return written;
}

}  // namespace passageMesh
