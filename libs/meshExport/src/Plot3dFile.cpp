#include "passageMesh/meshExport/Plot3dFile.hpp"

#include <sstream>

#include "passageMesh/core/AtomicFile.hpp"

namespace passageMesh {

std::string plot3dAscii(const StructuredMesh& mesh, double thickness) {
  std::ostringstream out;
  out << mesh.blocks.size() << '\n';
  for (const auto& b : mesh.blocks) out << b.ni << ' ' << b.nj << " 2\n";
  for (const auto& b : mesh.blocks) {
    int column = 0;
    const auto put = [&](double v) { out << formatExact(v) << (++column % 5 == 0 ? '\n' : ' '); };
    for (int k = 0; k < 2; ++k)
      for (const double v : b.x) put(v);
    for (int k = 0; k < 2; ++k)
      for (const double v : b.y) put(v);
    for (int k = 0; k < 2; ++k)
      for (std::size_t n = 0; n < b.x.size(); ++n) put(k * thickness);
    if (column % 5 != 0) out << '\n';
  }
  return out.str();
}

}  // namespace passageMesh
