#pragma once
// Meshes for the quality tests: small hand-built blocks and an algebraic HOH mesh.
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

#include "../blade/BladeTestData.hpp"
#include "../passage/PassageTestData.hpp"
#include "passageMesh/mesh/HohMesh.hpp"

namespace passageMesh::testData {

// A block named `name` with nodes x[i], y[j] (a tensor-product grid).
inline StructuredBlock tensorBlock(const std::string& name, const std::vector<double>& xs,
                                   const std::vector<double>& ys) {
  StructuredBlock b;
  b.name = name;
  b.ni = static_cast<int>(xs.size());
  b.nj = static_cast<int>(ys.size());
  for (double y : ys)
    for (double x : xs) {
      b.x.push_back(x);
      b.y.push_back(y);
    }
  return b;
}

// One cell as a 2 x 2-node O-block, corners counterclockwise from the first.
inline StructuredMesh singleCell(const std::array<Eigen::Vector2d, 4>& c) {
  StructuredBlock b;
  b.name = "OBlock";
  b.ni = b.nj = 2;
  // Node order i + 2 j: (0,0), (1,0), (0,1), (1,1).
  b.x = {c[0].x(), c[1].x(), c[3].x(), c[2].x()};
  b.y = {c[0].y(), c[1].y(), c[3].y(), c[2].y()};
  StructuredMesh mesh;
  mesh.blocks = {b};
  return mesh;
}

// The algebraic HOH mesh of the typical turbine blade at the paper's condition with
// nodes clustered at both edges (gamma = 2), a configuration whose cells are all valid;
// smaller than the paper's 30000 nodes to keep the tests fast.
inline HohMesh validHohMesh() {
  const BladeShape blade(typicalTurbineBlade());
  const double chord = blade.parameters().chord;
  PassageCondition condition = paperCondition(chord);
  condition.nO = 160 * 40;
  MeshingParameters parameters = MeshingParameters::defaults(chord);
  parameters.nT = 160;
  parameters.gammaLe = parameters.gammaTe = 2;
  return buildHohMesh(blade, condition, parameters);
}

// Node k of a range along one index.
inline std::array<int, 2> rangeNode(const NodeRange& r, int k) {
  auto sign = [](int v) { return (v > 0) - (v < 0); };
  return {r.begin[0] + k * sign(r.end[0] - r.begin[0]), r.begin[1] + k * sign(r.end[1] - r.begin[1])};
}

inline const BlockConnection& connectionNamed(const StructuredMesh& mesh, const std::string& name) {
  for (const auto& c : mesh.connections)
    if (c.name == name) return c;
  throw std::invalid_argument("no connection " + name);
}

}  // namespace passageMesh::testData
