#pragma once
// Where the central differences of the O-block find their neighbours beyond the block's
// own nodes (method.md section 5, docs/quality.md), read from the mesh's connections so
// that a mesh read back from CGNS works the same as one built in-process:
//
// - around the loop: the O-block is joined to itself from face i = 0 to face i = ni - 1
//   node for node (the seam, node i = 0 repeated as i = ni - 1), so i wraps;
// - beyond the outer row j = nj - 1 (the "ghost row" j = nj): an outer node joined to
//   one other face has as neighbour the node one step into that face's block (the H-block
//   node next to an O/H interface; across a periodic segment, the node one row inside the
//   opposite segment, moved by the connection's translation into this side's frame);
// - an outer node joined to two faces (the corners where an interface meets a periodic
//   segment) or to none (a physical boundary) has no ghost: one-sided differences.
#include <vector>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

// The neighbour of one outer O-block node across the outer boundary.
struct OuterNeighbour {
  int block = -1;      // -1: none (use one-sided differences)
  int node = 0;        // index into that block's x, y (i + ni * j)
  double dx = 0, dy = 0;  // added to that node's coordinates [m]
};

struct OBlockNeighbours {
  int oBlock = -1;
  bool wrapI = false;
  std::vector<OuterNeighbour> outer;  // one per i of the outer row
};

// The index of the block named "OBlock"; throws std::invalid_argument when there is none.
int findOBlock(const StructuredMesh& mesh);

// Fills `neighbours` (reusing its storage) for the O-block of `mesh`. Throws
// std::invalid_argument for a connection range that is not a run of nodes along a block
// edge, or connected ranges of different lengths.
void findOBlockNeighbours(const StructuredMesh& mesh, OBlockNeighbours& neighbours);

}  // namespace passageMesh
