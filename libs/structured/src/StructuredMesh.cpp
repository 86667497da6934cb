#include "passageMesh/structured/StructuredMesh.hpp"

#include <stdexcept>

namespace passageMesh {

namespace {

template <typename Mesh>
auto& blockNamed(Mesh& mesh, std::string_view name) {
  for (auto& b : mesh.blocks)
    if (b.name == name) return b;
  throw std::invalid_argument("StructuredMesh: no block named '" + std::string(name) + "'");
}

}  // namespace

StructuredBlock& StructuredMesh::block(std::string_view name) { return blockNamed(*this, name); }

const StructuredBlock& StructuredMesh::block(std::string_view name) const {
  return blockNamed(*this, name);
}

}  // namespace passageMesh
