// Q along each meshing parameter (issue 11 item 3): one tutorial at its passageDict, the
// other parameters at the defaults; nT from 250 to 450 in steps of 1, every other
// parameter over its whole range in steps of 1 % of the range. Writes one CSV per
// parameter (value, Q; Q = -1 for an invalid mesh) and prints the largest change of Q
// between neighbouring steps where both meshes are valid (docs/benchmarks.md); draws all
// ten curves into OUTPUT_DIR/TUTORIAL-qualityAlongParameters.png. With PARAMETER only
// that one (its CSV and the table row, no picture).
//
//   build/bench/qualityAlongParameters TUTORIAL OUTPUT_DIR [threads=2] [PARAMETER]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "TutorialPassage.hpp"
#include "passageMesh/core/GnuplotRun.hpp"
#include "passageMesh/core/ParallelFor.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/quality/MeshQuality.hpp"

using namespace passageMesh;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: qualityAlongParameters TUTORIAL OUTPUT_DIR [threads=2] [PARAMETER]\n");
    return 2;
  }
  const std::string name = argv[1];
  const std::filesystem::path output = argv[2];
  const int threads = argc > 3 ? std::max(1, std::atoi(argv[3])) : 2;
  const std::string only = argc > 4 ? argv[4] : "";
  const auto& names = MeshingParameters::names();
  if (!only.empty() && std::find(names.begin(), names.end(), only) == names.end()) {
    std::fprintf(stderr, "qualityAlongParameters: no meshing parameter '%s'\n", only.c_str());
    return 2;
  }
  const bench::TutorialPassage tutorial = bench::loadTutorialPassage(name);
  const BladeShape blade(tutorial.blade);
  const double chord = tutorial.blade.chord;
  const auto& condition = tutorial.condition;
  const MeshingParameters defaults = MeshingParameters::defaults(chord);
  const auto lower = MeshingParameters::lowerBounds(chord), upper = MeshingParameters::upperBounds(chord);
  std::filesystem::create_directories(output);
  std::printf("| parameter | steps | valid | steps with |dQ| > 0.005 | largest |dQ| between valid neighbours | at |\n"
              "|---|---|---|---|---|---|\n");
  GnuplotRun gnuplot;
  std::string script = gnuplotPngTerminal(2000, 900) + gnuplot.output(output / (name + "-qualityAlongParameters.png")) +
                       "set multiplot layout 2," + std::to_string((MeshingParameters::size + 1) / 2) + " title " + gnuplotQuoted(name + ": Q along each meshing parameter, the others at the defaults (invalid: not drawn)") + "\n"
                       "set datafile separator ','\nset key off\nset grid\nset ylabel 'Q'\n";
  for (int k = 0; k < MeshingParameters::size; ++k) {
    if (!only.empty() && names[k] != only) continue;
    const bool nT = names[k] == "nT";
    const bool isLength = MeshingParameters::table()[k].length;  // yIn, yOut: metres in the CSV, chords in the picture
    const int steps = nT ? 201 : 101;
    std::vector<double> value(steps), q(steps);
    for (int s = 0; s < steps; ++s)
      value[s] = nT ? 250 + s : lower[k] + (upper[k] - lower[k]) * s / (steps - 1);
    parallelFor(steps, threads, [&](int s) {
      auto a = defaults.toArray();
      a[static_cast<std::size_t>(k)] = value[static_cast<std::size_t>(s)];
      const HohMesh hoh = buildHohMesh(blade, condition, MeshingParameters::fromArray(a));
      q[static_cast<std::size_t>(s)] = hoh.valid ? computeMeshQuality(hoh.mesh).Q : invalidMeshQuality;
    });
    std::ofstream csv(output / (name + "-" + names[k] + ".csv"));
    csv << names[k] << ",Q\n";
    csv.precision(17);
    std::string plotted;
    double largest = 0, at = value[0];
    int valid = 0, above = 0;
    for (int s = 0; s < steps; ++s) {
      csv << value[s] << "," << q[s] << "\n";
      if (q[s] > invalidMeshQuality)
        plotted += std::to_string(nT ? value[s] : value[s] / (isLength ? chord : 1.0)) + "," + std::to_string(q[s]) + "\n";
      valid += q[s] > invalidMeshQuality;
      if (s > 0 && q[s] > invalidMeshQuality && q[s - 1] > invalidMeshQuality) {
        const double step = std::abs(q[s] - q[s - 1]);
        above += step > 0.005;  // the bar
        if (step > largest) largest = step, at = value[s];
      }
    }
    std::printf("| %s | %d | %d | %d | %.4f | %.6g |\n", names[k].c_str(), steps, valid, above, largest, at);
    script += "set xlabel " + gnuplotQuoted(names[k] + (isLength ? " [chords]" : "")) + "\nplot " +
              gnuplot.dataFile(plotted) + " using 1:2 with linespoints pt 7 ps 0.3\n";
    std::fflush(stdout);
  }
  if (only.empty()) gnuplot.run(script + "unset multiplot\n");
}
