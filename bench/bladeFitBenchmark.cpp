// bladeFitBenchmark: the tutorial fit table of docs/benchmarks.md.
//   build/bench/bladeFitBenchmark [repetitions=5] [threads=0]
// Fits each tutorial blade (tutorials/*/constant/bladePoints.dat) `repetitions` times and
// prints a Markdown table: deviations of the points from the fit beside ParaBlade's
// reference fits, and the median wall time of one fit.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "passageMesh/blade/BladeFit.hpp"
#include "passageMesh/blade/BladePoints.hpp"

using namespace passageMesh;

int main(int argc, char* argv[]) {
  const int repetitions = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  BladeFitOptions options;
  options.threads = argc > 2 ? std::atoi(argv[2]) : 0;
  struct Row {
    const char* blade;
    double paraBladeMean, paraBladeMax;  // shared/blades/README.md [m]
  };
  const Row rows[] = {{"LS89", 4.0e-5, 2.43e-4},
                      {"STD10", 1.1e-5, 5.8e-5},
                      {"T106A", 1e-6 * 99.4885, 5e-6 * 99.4885},
                      {"SIRT", 1.27e-4, 3.57e-4}};
  std::printf("| blade | points | mean dev. [m] | ParaBlade mean [m] | max dev. [m] | "
              "ParaBlade max [m] | max dev. [%% chord] | median time [s] |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const Row& row : rows) {
    const std::string file =
        std::string(PASSAGEMESH_SOURCE_DIR) + "/tutorials/" + row.blade + "/constant/bladePoints.dat";
    const auto ordered = orderBladePoints(readPointFile(file));
    std::vector<double> seconds;
    BladeFitResult fit;
    for (int r = 0; r < repetitions; ++r) {
      fit = fitBlade(ordered.points, options);
      seconds.push_back(fit.seconds);
    }
    std::sort(seconds.begin(), seconds.end());
    std::printf("| %s | %zu | %.3e | %.3e | %.3e | %.3e | %.4f | %.3f |\n", row.blade,
                ordered.points.size(), fit.meanDeviation, row.paraBladeMean, fit.maxDeviation,
                row.paraBladeMax, 100 * fit.maxDeviation / fit.parameters.chord,
                seconds[seconds.size() / 2]);
  }
  return 0;
}
