#pragma once
// Reading a plain-text file of 2-D points: one "x y" pair per line, blank lines and
// '#' comments (whole-line or trailing) allowed. Any other content is an InputError that
// names the file and the line. Format: docs/case-format.md.
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

namespace passageMesh {

struct PointSet {
  std::string file;                   // where the points came from, for messages
  std::vector<Eigen::Vector2d> points;
  std::vector<int> lines;             // the 1-based line of each point in `file`
};

PointSet readPointFile(const std::filesystem::path& file);

// Formats points as "x y" lines with 17 significant digits, after an optional header
// (each header line is written behind "# ").
std::string formatPointFile(const std::vector<Eigen::Vector2d>& points,
                            const std::vector<std::string>& header);

}  // namespace passageMesh
