#include "passageMesh/quality/OBlockNeighbours.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace passageMesh {
namespace {

int sign(int v) { return (v > 0) - (v < 0); }

int nodeCount(const NodeRange& r) {
  return std::abs(r.end[0] - r.begin[0]) + std::abs(r.end[1] - r.begin[1]) + 1;
}

// Node k of a range that runs along one index.
std::array<int, 2> nodeAt(const NodeRange& r, int k) {
  return {r.begin[0] + k * sign(r.end[0] - r.begin[0]), r.begin[1] + k * sign(r.end[1] - r.begin[1])};
}

const StructuredBlock& blockOf(const StructuredMesh& mesh, const NodeRange& r,
                               const std::string& connection) {
  if (r.block < 0 || r.block >= static_cast<int>(mesh.blocks.size()))
    throw std::invalid_argument("connection '" + connection + "': no block " +
                                std::to_string(r.block));
  return mesh.blocks[static_cast<std::size_t>(r.block)];
}

// The step from a face node into its block: +1 or -1 along the index fixed on the face.
std::array<int, 2> inwardStep(const StructuredBlock& b, const NodeRange& r,
                              const std::string& connection) {
  const bool alongI = r.begin[1] == r.end[1] && r.begin[0] != r.end[0];
  const bool alongJ = r.begin[0] == r.end[0] && r.begin[1] != r.end[1];
  if (!alongI && !alongJ)
    throw std::invalid_argument("connection '" + connection + "': a range is not along one index");
  const int axis = alongI ? 1 : 0;  // the index fixed on the face
  const int fixed = r.begin[static_cast<std::size_t>(axis)];
  const int size = axis == 0 ? b.ni : b.nj;
  std::array<int, 2> step{0, 0};
  if (fixed == 0) {
    step[static_cast<std::size_t>(axis)] = 1;
  } else if (fixed == size - 1) {
    step[static_cast<std::size_t>(axis)] = -1;
  } else {
    throw std::invalid_argument("connection '" + connection + "': a range is not on a block edge");
  }
  const auto last = nodeAt(r, nodeCount(r) - 1);
  for (const auto& node : {r.begin, last})
    if (node[0] < 0 || node[0] >= b.ni || node[1] < 0 || node[1] >= b.nj)
      throw std::invalid_argument("connection '" + connection + "': a range leaves its block");
  return step;
}

bool onOuterRow(const NodeRange& r, int oBlock, const StructuredBlock& o) {
  return r.block == oBlock && r.begin[1] == o.nj - 1 && r.end[1] == o.nj - 1;
}

// `own` on the O-block's outer row, `donor` the other side, `shift` taking donor
// coordinates into the O-block side's frame. Counts candidates per outer node in `count`.
void addOuterNeighbours(const StructuredMesh& mesh, const BlockConnection& c, const NodeRange& own,
                        const NodeRange& donor, double dx, double dy, OBlockNeighbours& out,
                        std::vector<int>& count) {
  const StructuredBlock& d = blockOf(mesh, donor, c.name);
  const auto step = inwardStep(d, donor, c.name);
  const int n = nodeCount(own);
  if (n != nodeCount(donor))
    throw std::invalid_argument("connection '" + c.name + "': ranges of different lengths");
  for (int k = 0; k < n; ++k) {
    const int i = nodeAt(own, k)[0];
    const auto dn = nodeAt(donor, k);
    ++count[static_cast<std::size_t>(i)];
    out.outer[static_cast<std::size_t>(i)] = {donor.block, dn[0] + step[0] + d.ni * (dn[1] + step[1]),
                                              dx, dy};
  }
}

// The seam: face i = 0 joined node for node (same j) to face i = ni - 1 of the same block.
bool isSeam(const BlockConnection& c, int oBlock, const StructuredBlock& o) {
  if (c.periodic || c.a.block != oBlock || c.b.block != oBlock) return false;
  if (c.a.begin[0] != c.a.end[0] || c.b.begin[0] != c.b.end[0]) return false;
  const int ia = c.a.begin[0], ib = c.b.begin[0];
  const bool oppositeEnds = (ia == 0 && ib == o.ni - 1) || (ia == o.ni - 1 && ib == 0);
  const auto [ja0, ja1] = std::minmax(c.a.begin[1], c.a.end[1]);
  return oppositeEnds && ja0 == 0 && ja1 == o.nj - 1 && c.a.begin[1] == c.b.begin[1] &&
         c.a.end[1] == c.b.end[1];
}

}  // namespace

int findOBlock(const StructuredMesh& mesh) {
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    if (mesh.blocks[b].name == "OBlock") return static_cast<int>(b);
  throw std::invalid_argument("mesh quality: the mesh has no block named OBlock");
}

void findOBlockNeighbours(const StructuredMesh& mesh, OBlockNeighbours& out) {
  out.oBlock = findOBlock(mesh);
  const StructuredBlock& o = mesh.blocks[static_cast<std::size_t>(out.oBlock)];
  out.wrapI = false;
  out.outer.assign(static_cast<std::size_t>(o.ni), OuterNeighbour{});
  // Candidates per outer node; thread_local so that repeated calls do not allocate.
  thread_local std::vector<int> count;
  count.assign(static_cast<std::size_t>(o.ni), 0);
  for (const BlockConnection& c : mesh.connections) {
    out.wrapI = out.wrapI || isSeam(c, out.oBlock, o);
    const double tx = c.periodic ? c.translation.x() : 0.0;
    const double ty = c.periodic ? c.translation.y() : 0.0;
    // b = a + translation: a's side sees b's nodes moved by -translation, and vice versa.
    if (onOuterRow(c.a, out.oBlock, o)) addOuterNeighbours(mesh, c, c.a, c.b, -tx, -ty, out, count);
    if (onOuterRow(c.b, out.oBlock, o)) addOuterNeighbours(mesh, c, c.b, c.a, tx, ty, out, count);
  }
  for (std::size_t i = 0; i < count.size(); ++i)
    if (count[i] != 1) out.outer[i].block = -1;  // a corner (or no connection): one-sided
}

}  // namespace passageMesh
