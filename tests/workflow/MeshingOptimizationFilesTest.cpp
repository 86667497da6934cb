// The files of a meshing-parameter optimisation and its progress line, without meshes:
// a made-up run is enough for what is written where.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "../utilities/UtilityTestSupport.hpp"
#include "passageMesh/optimize/MeshingParameterSpace.hpp"
#include "passageMesh/workflow/MeshingOptimizationFiles.hpp"
#include "passageMesh/workflow/OptimizationProgressLine.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;

namespace {

namespace fs = std::filesystem;

// Two evaluations: the defaults (Q 0.3) and a better point (Q 0.4).
MeshingOptimization madeUpRun(double secondQ) {
  MeshingOptimization run;
  run.box = meshingParameterProblem(1.0);
  MeshingParameters better = MeshingParameters::defaults(1.0);
  better.nT = 222;
  const std::vector<std::pair<MeshingParameters, double>> evaluations = {
      {MeshingParameters::defaults(1.0), 0.3}, {better, secondQ}};
  double best = -INFINITY;
  for (const auto& [p, q] : evaluations) {
    best = std::max(best, q);
    run.result.history.push_back({static_cast<long>(run.result.history.size()), toOptimizerVector(p), q, best});
  }
  run.result.bestValue = best;
  run.result.evaluations = 2;
  run.best = secondQ > 0.3 ? better : evaluations[0].first;
  run.result.best = toOptimizerVector(run.best);
  return run;
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = tempFolder("workflow") / name;
  fs::remove_all(dir);
  fs::create_directories(dir / "system");
  return dir;
}

}  // namespace

TEST(MeshingOptimizationFiles, WithoutGnuplotWarnsAndRemovesAStalePlot) {
  const fs::path dir = freshDir("noGnuplot");
  const fs::path png = dir / "postProcessing" / "iterOptimize" / "convergence.png";
  fs::create_directories(png.parent_path());
  std::ofstream(png) << "an earlier run's plot";
  const auto files = writeMeshingOptimizationFiles(dir, madeUpRun(0.4), "/nonexistent/gnuplot");
  ASSERT_EQ(files.warnings.size(), 1u);
  EXPECT_NE(files.warnings[0].find("not installed"), std::string::npos) << files.warnings[0];
  EXPECT_FALSE(fs::exists(png));
  EXPECT_TRUE(fs::exists(dir / "postProcessing" / "iterOptimize" / "history.csv"));
  EXPECT_EQ(readMeshDict(dir / "system" / "meshDict.xml", 1.0).nT, 222);
  // No meshDict.xml before: nothing to keep.
  EXPECT_FALSE(fs::exists(dir / "system" / "meshDict.xml.orig"));
}

TEST(MeshingOptimizationFiles, KeepsTheFirstMeshDictOnlyOnce) {
  const fs::path dir = freshDir("orig");
  std::ofstream(dir / "system" / "meshDict.xml") << "<meshDict><nT>150</nT></meshDict>\n";
  writeMeshingOptimizationFiles(dir, madeUpRun(0.4), "/nonexistent/gnuplot");
  writeMeshingOptimizationFiles(dir, madeUpRun(0.4), "/nonexistent/gnuplot");
  EXPECT_EQ(readText(dir / "system" / "meshDict.xml.orig"), "<meshDict><nT>150</nT></meshDict>\n");
  EXPECT_EQ(readMeshDict(dir / "system" / "meshDict.xml", 1.0).nT, 222);
}

TEST(MeshingOptimizationFiles, NoValidMeshLeavesMeshDictAlone) {
  const fs::path dir = freshDir("invalid");
  MeshingOptimization run = madeUpRun(-1);
  for (auto& e : run.result.history) e.value = e.bestSoFar = -1;
  run.result.bestValue = -1;
  const auto files = writeMeshingOptimizationFiles(dir, run, "/nonexistent/gnuplot");
  EXPECT_FALSE(fs::exists(dir / "system" / "meshDict.xml"));
  EXPECT_TRUE(fs::exists(dir / "postProcessing" / "iterOptimize" / "history.csv"));
  ASSERT_EQ(files.warnings.size(), 2u);
  EXPECT_NE(files.warnings[0].find("no valid mesh"), std::string::npos);
}

TEST(OptimizationProgressLine, SaysDoneBestAndTimeLeft) {
  EXPECT_EQ(formatDuration(3.4), "3 s");
  EXPECT_EQ(formatDuration(125), "2 min 5 s");
  EXPECT_EQ(formatDuration(3725), "1 h 2 min");
  EXPECT_EQ(formatOptimizationProgress({20, 100, 0.5}, 30.0),
            "20/100 evaluations, best Q 0.50000, 1.5 s per evaluation, 2 min 0 s left");
}
