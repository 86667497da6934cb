#include "passageMesh/meshExport/UnstructuredPassage.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace passageMesh {

namespace {

// The nodes of a range in its own direction, as (block-local) node indices.
std::vector<int> rangeNodes(const StructuredMesh& mesh, const NodeRange& r) {
  const StructuredBlock& b = mesh.blocks.at(static_cast<std::size_t>(r.block));
  const int di = r.end[0] - r.begin[0], dj = r.end[1] - r.begin[1];
  const bool onEdge = (di == 0 && (r.begin[0] == 0 || r.begin[0] == b.ni - 1)) ||
                      (dj == 0 && (r.begin[1] == 0 || r.begin[1] == b.nj - 1));
  if ((di != 0 && dj != 0) || (di == 0 && dj == 0) || !onEdge)
    throw std::invalid_argument("a range of block " + b.name + " is not a run of nodes along an edge");
  const int n = std::max(std::abs(di), std::abs(dj)) + 1;
  const int si = (di > 0) - (di < 0), sj = (dj > 0) - (dj < 0);
  std::vector<int> nodes;
  for (int k = 0; k < n; ++k) {
    const int i = r.begin[0] + si * k, j = r.begin[1] + sj * k;
    if (i < 0 || i >= b.ni || j < 0 || j >= b.nj)
      throw std::invalid_argument("a range of block " + b.name + " leaves the block");
    nodes.push_back(i + b.ni * j);
  }
  return nodes;
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(static_cast<std::size_t>(n)) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  int find(int a) {
    while (parent[static_cast<std::size_t>(a)] != a)
      a = parent[static_cast<std::size_t>(a)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
    return a;
  }
  void join(int a, int b) {  // the smaller root wins: the first appearance names the point
    a = find(a), b = find(b);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
};

std::uint64_t edgeKey(int a, int b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

class Builder {
 public:
  explicit Builder(const StructuredMesh& mesh) : mesh_(mesh) {
    for (const auto& b : mesh.blocks) {
      offsets_.push_back(total_);
      total_ += b.ni * b.nj;
    }
  }

  UnstructuredPassage build() {
    mergeNodes();
    makeCells();
    for (const BoundaryPatch& p : mesh_.patches) addPatch(p.name, kindOf(p.type), p.range);
    addPeriodicPatches();
    std::size_t boundaryEdges = 0;
    for (const auto& [key, edge] : edges_) {
      if (edge.neighbour >= 0) result_.internalEdges.push_back(edge);
      else ++boundaryEdges;
    }
    std::size_t named = 0;
    for (const auto& p : result_.patches) named += p.edges.size();
    if (named != boundaryEdges)
      throw std::invalid_argument(std::to_string(boundaryEdges - named) +
                                  " boundary edges belong to no patch or connection");
    std::sort(result_.internalEdges.begin(), result_.internalEdges.end(),
              [](const MeshEdge& a, const MeshEdge& b) {
                return a.owner != b.owner ? a.owner < b.owner : a.neighbour < b.neighbour;
              });
    return std::move(result_);
  }

 private:
  const StructuredMesh& mesh_;
  std::vector<int> offsets_;
  int total_ = 0;
  std::vector<int> pointOf_;  // global node -> point
  std::unordered_map<std::uint64_t, MeshEdge> edges_;
  UnstructuredPassage result_;

  int globalNode(int block, int node) const { return offsets_[static_cast<std::size_t>(block)] + node; }
  int point(int block, int node) const { return pointOf_[static_cast<std::size_t>(globalNode(block, node))]; }

  static EdgePatchKind kindOf(PatchType t) {
    return t == PatchType::wall ? EdgePatchKind::wall
           : t == PatchType::inlet ? EdgePatchKind::inlet : EdgePatchKind::outlet;
  }

  void mergeNodes() {
    UnionFind sets(total_);
    for (const BlockConnection& c : mesh_.connections) {
      const auto a = rangeNodes(mesh_, c.a), b = rangeNodes(mesh_, c.b);
      if (a.size() != b.size()) throw std::invalid_argument("connection " + c.name + ": ranges of different lengths");
      if (c.periodic) continue;
      for (std::size_t k = 0; k < a.size(); ++k) sets.join(globalNode(c.a.block, a[k]), globalNode(c.b.block, b[k]));
    }
    std::vector<int> pointOfRoot(static_cast<std::size_t>(total_), -1);
    pointOf_.resize(static_cast<std::size_t>(total_));
    for (std::size_t blk = 0; blk < mesh_.blocks.size(); ++blk) {
      const StructuredBlock& b = mesh_.blocks[blk];
      for (int n = 0; n < b.ni * b.nj; ++n) {
        const int g = globalNode(static_cast<int>(blk), n);
        int& p = pointOfRoot[static_cast<std::size_t>(sets.find(g))];
        if (p < 0) {
          p = static_cast<int>(result_.points.size());
          result_.points.emplace_back(b.x[static_cast<std::size_t>(n)], b.y[static_cast<std::size_t>(n)]);
        }
        pointOf_[static_cast<std::size_t>(g)] = p;
      }
    }
  }

  void makeCells() {
    for (std::size_t blk = 0; blk < mesh_.blocks.size(); ++blk) {
      const StructuredBlock& b = mesh_.blocks[blk];
      const int block = static_cast<int>(blk);
      for (int j = 0; j + 1 < b.nj; ++j)
        for (int i = 0; i + 1 < b.ni; ++i) {
          const std::array<int, 4> c = {point(block, i + b.ni * j), point(block, i + 1 + b.ni * j),
                                        point(block, i + 1 + b.ni * (j + 1)), point(block, i + b.ni * (j + 1))};
          const int cell = static_cast<int>(result_.cells.size());
          for (int k = 0; k < 4; ++k) addCellEdge(c[k], c[(k + 1) % 4], cell, b.name, i, j);
          result_.cells.push_back(c);
        }
    }
  }

  void addCellEdge(int p0, int p1, int cell, const std::string& block, int i, int j) {
    if (p0 == p1)
      throw std::invalid_argument("cell (" + std::to_string(i) + ", " + std::to_string(j) + ") of block " +
                                  block + " collapses: two corners are one node");
    auto [it, added] = edges_.try_emplace(edgeKey(p0, p1), MeshEdge{p0, p1, cell, -1});
    if (added) return;
    if (it->second.neighbour >= 0)
      throw std::invalid_argument("an edge of cell (" + std::to_string(i) + ", " + std::to_string(j) +
                                  ") of block " + block + " is shared by more than two cells");
    it->second.neighbour = cell;  // cells come in increasing order: the first one owns
  }

  EdgePatch& patchNamed(const std::string& name, EdgePatchKind kind) {
    for (auto& p : result_.patches)
      if (p.name == name) return p;
    result_.patches.push_back({name, kind, {}});
    return result_.patches.back();
  }

  void addPatch(const std::string& name, EdgePatchKind kind, const NodeRange& range) {
    EdgePatch& patch = patchNamed(name, kind);
    const auto nodes = rangeNodes(mesh_, range);
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
      const auto it = edges_.find(edgeKey(point(range.block, nodes[k]), point(range.block, nodes[k + 1])));
      if (it == edges_.end() || it->second.neighbour >= 0)
        throw std::invalid_argument("patch " + name + " lies on an internal edge");
      patch.edges.push_back(it->second);
    }
  }

  void addPeriodicPatches() {
    bool first = true;
    for (const BlockConnection& c : mesh_.connections) {
      if (!c.periodic) continue;
      // Lower is the side the translation lifts in +y (or, for an axial one, in +x).
      const bool aIsLower = c.translation.y() > 0 || (c.translation.y() == 0 && c.translation.x() > 0);
      const Eigen::Vector2d t = aIsLower ? c.translation : Eigen::Vector2d(-c.translation);
      if (first) result_.translation = t;
      if ((t - result_.translation).norm() > 1e-9 * std::max(1.0, t.norm()))
        throw std::invalid_argument("periodic connection " + c.name + " has a different translation");
      first = false;
      addPatch("periodicLower", EdgePatchKind::periodicLower, aIsLower ? c.a : c.b);
      addPatch("periodicUpper", EdgePatchKind::periodicUpper, aIsLower ? c.b : c.a);
    }
  }
};

}  // namespace

UnstructuredPassage makeUnstructuredPassage(const StructuredMesh& mesh) { return Builder(mesh).build(); }

}  // namespace passageMesh
