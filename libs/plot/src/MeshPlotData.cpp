#include "passageMesh/plot/MeshPlotData.hpp"

#include <sstream>

#include "passageMesh/core/NumberFormat.hpp"

namespace passageMesh {

namespace {

void node(std::ostringstream& out, const StructuredBlock& b, int i, int j) {
  out << formatExact(b.xAt(i, j)) << ' ' << formatExact(b.yAt(i, j)) << '\n';
}

bool drawn(int line, int last, int stride) { return line % stride == 0 || line == last; }

}  // namespace

std::string gridLinesData(const StructuredMesh& mesh, int stride) {
  std::ostringstream out;
  for (const StructuredBlock& b : mesh.blocks) {
    for (int j = 0; j < b.nj; ++j) {
      if (!drawn(j, b.nj - 1, stride)) continue;
      for (int i = 0; i < b.ni; ++i) node(out, b, i, j);
      out << '\n';
    }
    for (int i = 0; i < b.ni; ++i) {
      if (!drawn(i, b.ni - 1, stride)) continue;
      for (int j = 0; j < b.nj; ++j) node(out, b, i, j);
      out << '\n';
    }
  }
  return out.str();
}

std::string cellValuesData(const StructuredBlock& block, const std::vector<double>& values) {
  static const int corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::ostringstream out;
  for (int j = 0; j + 1 < block.nj; ++j)
    for (int i = 0; i + 1 < block.ni; ++i) {
      const std::string v = formatExact(values[static_cast<std::size_t>(i + (block.ni - 1) * j)]);
      for (const auto& c : corner)
        out << formatExact(block.xAt(i + c[0], j + c[1])) << ' ' << formatExact(block.yAt(i + c[0], j + c[1]))
            << ' ' << v << '\n';
      out << '\n';  // the next cell is a polygon of its own
    }
  return out.str();
}

std::string nodeRowData(const StructuredBlock& block, int j) {
  std::ostringstream out;
  for (int i = 0; i < block.ni; ++i) node(out, block, i, j);
  return out.str();
}

}  // namespace passageMesh
