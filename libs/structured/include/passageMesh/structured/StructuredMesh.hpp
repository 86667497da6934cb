#pragma once
// A 2-D multi-block structured mesh as the exporters see it: blocks of nodes, the 1-to-1
// connections between block faces (including periodic ones), and the boundary patches.
// ellipticMesh fills one; writeCgns and writeVtm write it (docs/case-format.md).
//
// Indexing: a block has ni x nj nodes; node (i, j), 0-based, is stored at i + ni * j.
// A face range is a run of nodes along one block edge, given by its first and last node
// (0-based, inclusive); the two ends may be given in either order, which fixes the
// direction the range runs.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace passageMesh {

struct StructuredBlock {
  std::string name;
  int ni = 0, nj = 0;
  std::vector<double> x, y;  // [m], size ni * nj

  double& xAt(int i, int j) { return x[static_cast<std::size_t>(i + ni * j)]; }
  double& yAt(int i, int j) { return y[static_cast<std::size_t>(i + ni * j)]; }
  double xAt(int i, int j) const { return x[static_cast<std::size_t>(i + ni * j)]; }
  double yAt(int i, int j) const { return y[static_cast<std::size_t>(i + ni * j)]; }
};

struct NodeRange {
  int block = 0;                 // index into StructuredMesh::blocks
  std::array<int, 2> begin{};    // (i, j) of the first node
  std::array<int, 2> end{};      // (i, j) of the last node
};

// Node k of `a` coincides with node k of `b` (after adding `translation` to `a`'s nodes
// for a periodic connection): both ranges hold the same number of nodes.
struct BlockConnection {
  std::string name;
  NodeRange a, b;
  bool periodic = false;
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();  // b = a + translation [m]
};

enum class PatchType { wall, inlet, outlet };

struct BoundaryPatch {
  std::string name;    // also the CGNS family name, e.g. "blade", "inlet", "outlet"
  PatchType type = PatchType::wall;
  NodeRange range;
};

struct StructuredMesh {
  std::vector<StructuredBlock> blocks;
  std::vector<BlockConnection> connections;
  std::vector<BoundaryPatch> patches;

  // The (first) block named `name`; throws std::invalid_argument naming it when there is
  // none. Connections and patches still refer to blocks by index.
  StructuredBlock& block(std::string_view name);
  const StructuredBlock& block(std::string_view name) const;
};

// True when no node of any block has an infinite or NaN coordinate.
inline bool hasOnlyFiniteCoordinates(const StructuredMesh& mesh) {
  for (const auto& b : mesh.blocks)
    for (std::size_t n = 0; n < b.x.size(); ++n)
      if (!std::isfinite(b.x[n]) || !std::isfinite(b.y[n])) return false;
  return true;
}

}  // namespace passageMesh
