#include "passageMesh/meshExport/BladeEdges.hpp"

#include <stdexcept>

namespace passageMesh {

BladeEdges findBladeEdges(const StructuredMesh& mesh) {
  for (const StructuredBlock& o : mesh.blocks) {
    if (o.name != "OBlock") continue;
    BladeEdges edges;
    edges.trailingEdge = {o.xAt(0, 0), o.yAt(0, 0)};
    edges.leadingEdge = edges.trailingEdge;
    for (int i = 1; i < o.ni; ++i)
      if (o.xAt(i, 0) < edges.leadingEdge.x()) edges.leadingEdge = {o.xAt(i, 0), o.yAt(i, 0)};
    edges.chord = (edges.leadingEdge - edges.trailingEdge).norm();
    return edges;
  }
  throw std::invalid_argument("the mesh has no block named OBlock");
}

}  // namespace passageMesh
