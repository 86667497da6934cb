#include "passageMesh/core/PointFile.hpp"

#include <fstream>
#include <sstream>

#include "passageMesh/core/Dictionary.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/NumberFormat.hpp"

namespace passageMesh {

PointSet readPointFile(const std::filesystem::path& file) {
  PointSet set;
  set.file = file.string();
  if (!std::filesystem::is_regular_file(file))
    throw InputError(set.file, 0, "file not found (expected 'x y' points, one pair per line)");
  std::ifstream in(file);
  if (!in) throw InputError(set.file, 0, "cannot open file");
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (lineNumber == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 BOM
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::vector<std::string> fields;
    for (std::string word; words >> word;) fields.push_back(word);
    if (fields.empty()) continue;
    if (fields.size() != 2)
      throw InputError(set.file, lineNumber,
                       "expected two numbers 'x y', found " + std::to_string(fields.size()) +
                           " field(s)");
    Eigen::Vector2d p;
    for (int k = 0; k < 2; ++k)
      if (!parseFiniteDouble(fields[k], p[k]))
        throw InputError(set.file, lineNumber,
                         "expected a finite number for " + std::string(k ? "y" : "x") +
                             ", found '" + fields[k] + "'");
    set.points.push_back(p);
    set.lines.push_back(lineNumber);
  }
  if (set.points.empty()) throw InputError(set.file, 0, "no points found (empty file?)");
  return set;
}

std::string formatPointFile(const std::vector<Eigen::Vector2d>& points,
                            const std::vector<std::string>& header) {
  std::string out;
  out.reserve(points.size() * 48 + 256);
  for (const auto& h : header) out += "# " + h + "\n";
  for (const auto& p : points) out += formatExact(p.x()) + " " + formatExact(p.y()) + "\n";
  return out;
}

}  // namespace passageMesh
