// plotMesh: PNG pictures of the case's mesh, its quality and the fitted blade, drawn by
// gnuplot without a display (MeshPictures.hpp lists them).
//   reads  mesh/passage.cgns; constant/bladePoints.dat and constant/bladeProfile.dat
//          when both exist (else the blade picture is skipped with a warning)
//   writes postProcessing/plots/*.png, all together or none
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/quality/MeshQualityReport.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/PointFile.hpp"
#include "passageMesh/structured/CgnsReader.hpp"
#include "passageMesh/plot/MeshPictures.hpp"

using namespace passageMesh;

int main(int argc, char* argv[]) {
  return runUtility("plotMesh", [&] {
    CommandLine cli("plotMesh",
                    "Draws PNG pictures of mesh/passage.cgns (whole passage, edge zooms, O-block\n"
                    "cells coloured by Q_S and Q_J) and of the fitted blade over its input points\n"
                    "into postProcessing/plots/ with gnuplot.");
    if (!cli.parse(argc, argv)) return 0;
    const auto& dir = cli.caseDir();
    const auto cgnsFile = dir / "mesh" / "passage.cgns";
    const auto [mesh, quality] = readMeshWithQuality(cgnsFile);
    const auto pointsFile = dir / "constant" / "bladePoints.dat";
    const auto profileFile = dir / "constant" / "bladeProfile.dat";
    BladeCurves blade;
    const bool haveBlade = std::filesystem::exists(pointsFile) && std::filesystem::exists(profileFile);
    if (haveBlade) {
      blade.inputPoints = readPointFile(pointsFile).points;
      blade.profile = readPointFile(profileFile).points;
    } else {
      std::cerr << "plotMesh: warning: no blade picture: " << pointsFile.string() << " or "
                << profileFile.string() << " is missing\n";
    }
    const auto folder = dir / "postProcessing" / "plots";
    const auto pictures = drawMeshPictures(mesh, quality, haveBlade ? &blade : nullptr, folder);
    std::printf("plotMesh: %s (Q = %.4f%s)\n", cgnsFile.string().c_str(), quality.Q,
                quality.valid ? "" : ", INVALID MESH");
    for (const auto& p : pictures) std::printf("  wrote %s\n", p.lexically_relative(dir).string().c_str());
    return 0;
  });
}
