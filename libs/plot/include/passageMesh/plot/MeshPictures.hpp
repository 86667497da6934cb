#pragma once
// plotMesh's PNG pictures of a passage mesh, drawn by gnuplot (GnuplotRun: all pictures
// appear together or none). Equal axis scales everywhere; lengths in metres.
//
//   passage.png       every block, every second grid line (as the method paper's figures)
//   leadingEdge.png   every grid line in a square 8 % of the chord wide around each edge
//   trailingEdge.png
//   qualityQS.png     O-block cells filled by Q_S: the whole block and a zoom on the worst
//   qualityQJ.png     cell (marked in both); the title gives min, mean and the mesh's Q
//   blade.png         the fitted profile over the input points (only with a BladeCurves)
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "passageMesh/structured/StructuredMesh.hpp"
#include "passageMesh/quality/MeshQuality.hpp"

namespace passageMesh {

struct BladeCurves {
  std::vector<Eigen::Vector2d> inputPoints;  // constant/bladePoints.dat
  std::vector<Eigen::Vector2d> profile;      // constant/bladeProfile.dat
};

// The share of the chord each zoom box spans.
inline constexpr double zoomBoxChords = 0.08;

// `quality` must hold every block's cell values (MeshQualityOptions::everyBlock). Returns
// the pictures written into `folder`. Throws std::invalid_argument for a mesh without an
// O-block or without cell values, std::runtime_error (one line) when gnuplot is missing or
// fails; then no picture is replaced.
std::vector<std::filesystem::path> drawMeshPictures(const StructuredMesh& mesh,
                                                    const MeshQuality& quality,
                                                    const BladeCurves* blade,
                                                    const std::filesystem::path& folder,
                                                    const std::string& gnuplot = "gnuplot");

}  // namespace passageMesh
