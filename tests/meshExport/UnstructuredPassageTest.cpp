// The HOH mesh as one unstructured mesh: merged interface nodes, upper-triangular internal
// edges, every edge counterclockwise around its owner, periodic edges paired by index.
#include <gtest/gtest.h>

#include "../quality/QualityTestData.hpp"
#include "passageMesh/meshExport/BladeEdges.hpp"
#include "passageMesh/meshExport/UnstructuredPassage.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;

namespace {

// Twice the signed area of the triangle (a, b, c): positive when c lies left of a -> b.
double leftOf(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Eigen::Vector2d u = b - a, v = c - a;
  return u.x() * v.y() - u.y() * v.x();
}

Eigen::Vector2d centre(const UnstructuredPassage& p, int cell) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const int k : p.cells[static_cast<std::size_t>(cell)]) sum += p.points[static_cast<std::size_t>(k)];
  return sum / 4;
}

const EdgePatch& patch(const UnstructuredPassage& p, const std::string& name) {
  for (const auto& e : p.patches)
    if (e.name == name) return e;
  throw std::runtime_error("no patch " + name);
}

}  // namespace

TEST(UnstructuredPassage, MergesInterfacesAndOrdersEdges) {
  const HohMesh hoh = validHohMesh();
  ASSERT_TRUE(hoh.valid) << hoh.problem;
  const UnstructuredPassage p = makeUnstructuredPassage(hoh.mesh);
  std::size_t cells = 0, nodes = 0, merged = 0;
  for (const auto& b : hoh.mesh.blocks) {
    cells += static_cast<std::size_t>((b.ni - 1) * (b.nj - 1));
    nodes += static_cast<std::size_t>(b.ni * b.nj);
  }
  for (const auto& c : hoh.mesh.connections)
    if (!c.periodic) merged += static_cast<std::size_t>(std::abs(c.a.end[0] - c.a.begin[0]) + std::abs(c.a.end[1] - c.a.begin[1]) + 1);
  EXPECT_EQ(p.cells.size(), cells);
  // Two interface corners are shared by two connections each (inlet/outlet interface and
  // the O-block seam meet only at the outlet corner): at most a few nodes merged twice.
  EXPECT_LE(p.points.size(), nodes - merged + 4);
  EXPECT_GE(p.points.size(), nodes - merged);
  for (std::size_t k = 0; k < p.internalEdges.size(); ++k) {
    const MeshEdge& e = p.internalEdges[k];
    ASSERT_LT(e.owner, e.neighbour);
    if (k > 0) {
      const MeshEdge& previous = p.internalEdges[k - 1];
      ASSERT_TRUE(previous.owner < e.owner || (previous.owner == e.owner && previous.neighbour < e.neighbour));
    }
    EXPECT_GT(leftOf(p.points[e.p0], p.points[e.p1], centre(p, e.owner)), 0);
    EXPECT_LT(leftOf(p.points[e.p0], p.points[e.p1], centre(p, e.neighbour)), 0);
  }
  // Euler: every cell has four edges, each internal edge counted twice.
  std::size_t boundary = 0;
  for (const auto& e : p.patches) boundary += e.edges.size();
  EXPECT_EQ(4 * p.cells.size(), 2 * p.internalEdges.size() + boundary);
}

TEST(UnstructuredPassage, PatchesNamedAndPeriodicEdgesPaired) {
  const HohMesh hoh = validHohMesh();
  const UnstructuredPassage p = makeUnstructuredPassage(hoh.mesh);
  ASSERT_EQ(p.patches.size(), 5u);
  EXPECT_EQ(patch(p, "blade").kind, EdgePatchKind::wall);
  EXPECT_EQ(patch(p, "blade").edges.size(), static_cast<std::size_t>(hoh.mesh.blocks[1].ni - 1));
  EXPECT_EQ(patch(p, "inlet").kind, EdgePatchKind::inlet);
  EXPECT_EQ(patch(p, "outlet").kind, EdgePatchKind::outlet);
  const EdgePatch& lower = patch(p, "periodicLower");
  const EdgePatch& upper = patch(p, "periodicUpper");
  ASSERT_EQ(lower.edges.size(), upper.edges.size());
  EXPECT_GT(p.translation.y(), 0);
  EXPECT_NEAR(p.translation.x(), 0, 1e-12);
  const double tolerance = 1e-9 * p.translation.norm();
  for (std::size_t k = 0; k < lower.edges.size(); ++k) {
    const auto& l = lower.edges[k];
    const auto& u = upper.edges[k];
    // Opposite directions: lower p0 meets upper p1.
    EXPECT_LT((p.points[l.p0] + p.translation - p.points[u.p1]).norm(), tolerance) << k;
    EXPECT_LT((p.points[l.p1] + p.translation - p.points[u.p0]).norm(), tolerance) << k;
    EXPECT_EQ(l.neighbour, -1);
  }
}

TEST(UnstructuredPassage, UnnamedBoundaryIsRefused) {
  HohMesh hoh = validHohMesh();
  hoh.mesh.patches.pop_back();  // the outlet
  EXPECT_THROW(makeUnstructuredPassage(hoh.mesh), std::invalid_argument);
}

TEST(UnstructuredPassage, CollapsedCellIsRefused) {
  HohMesh hoh = validHohMesh();
  // A connection joining two nodes of one cell edge collapses it.
  hoh.mesh.connections.push_back({"bad", NodeRange{1, {0, 0}, {1, 0}}, NodeRange{1, {1, 0}, {2, 0}}, false,
                                  Eigen::Vector2d::Zero()});
  EXPECT_THROW(makeUnstructuredPassage(hoh.mesh), std::invalid_argument);
}

TEST(BladeEdges, TrailingEdgeIsTheFirstWallNodeAndLeadingEdgeTheMostUpstream) {
  const HohMesh hoh = validHohMesh();
  const StructuredBlock& o = hoh.mesh.blocks[1];
  const BladeEdges e = findBladeEdges(hoh.mesh);
  EXPECT_EQ(e.trailingEdge, Eigen::Vector2d(o.xAt(0, 0), o.yAt(0, 0)));
  for (int i = 0; i < o.ni; ++i) EXPECT_GE(o.xAt(i, 0), e.leadingEdge.x());
  EXPECT_DOUBLE_EQ(e.chord, (e.leadingEdge - e.trailingEdge).norm());
  EXPECT_NEAR(e.chord, typicalTurbineBlade().chord, 0.05 * typicalTurbineBlade().chord);
  StructuredMesh noOBlock = hoh.mesh;
  noOBlock.blocks[1].name = "other";
  EXPECT_THROW(findBladeEdges(noOBlock), std::invalid_argument);
}
