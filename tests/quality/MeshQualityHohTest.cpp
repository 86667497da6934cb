// Q of a whole HOH mesh: invariance under similarity transforms, the neighbour rules
// across the periodic segments, the O/H interfaces, the seam, the blade and the
// interface corners, and the invalid-mesh value.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <stdexcept>

#include "QualityTestData.hpp"
#include "../TestFiles.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/quality/MeshQuality.hpp"
#include "passageMesh/quality/MeshQualityReport.hpp"
#include "passageMesh/quality/OBlockNeighbours.hpp"
#include "passageMesh/structured/CgnsReader.hpp"
#include "passageMesh/structured/CgnsWriter.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;

namespace {

// J = x_xi y_eta - x_eta y_xi from the two difference vectors.
double jacobianOf(const Eigen::Vector2d& xi, const Eigen::Vector2d& eta) {
  return xi.x() * eta.y() - eta.x() * xi.y();
}

Eigen::Vector2d nodeOf(const StructuredBlock& b, int i, int j) { return {b.xAt(i, j), b.yAt(i, j)}; }

void moveNode(StructuredBlock& b, int i, int j, const Eigen::Vector2d& p) {
  b.xAt(i, j) = p.x();
  b.yAt(i, j) = p.y();
}

// The cells having node (i, j) of the O-block as a corner.
void addCellsAround(const StructuredBlock& o, int i, int j, std::set<std::pair<int, int>>& cells) {
  for (int ci : {i - 1, i})
    for (int cj : {j - 1, j})
      if (ci >= 0 && ci + 1 < o.ni && cj >= 0 && cj + 1 < o.nj) cells.insert({ci, cj});
}

// Q_J of cell (i, j) from the node Jacobians.
double cellQJ(const StructuredBlock& o, const std::vector<double>& J, int i, int j) {
  auto at = [&](int a, int b) { return J[static_cast<std::size_t>(a + o.ni * b)]; };
  const double c[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
  return std::min({c[0], c[1], c[2], c[3]}) / std::max({c[0], c[1], c[2], c[3]});
}

// Cells outside `affected` keep their Q_J bit for bit; inside, Q_J is min / max of the
// corner Jacobians in `J` (the O-block's node J of the changed mesh).
void expectOnlyAffectedCellsChange(const StructuredBlock& o, const std::vector<double>& J,
                                   const std::vector<double>& before,
                                   const std::vector<double>& after,
                                   const std::set<std::pair<int, int>>& affected) {
  for (int j = 0; j + 1 < o.nj; ++j)
    for (int i = 0; i + 1 < o.ni; ++i) {
      const auto cell = static_cast<std::size_t>(i + (o.ni - 1) * j);
      if (affected.count({i, j}))
        EXPECT_NEAR(after[cell], cellQJ(o, J, i, j), 1e-14) << i << " " << j;
      else
        EXPECT_EQ(after[cell], before[cell]) << i << " " << j;
    }
}

class HohQuality : public ::testing::Test {
 protected:
  void SetUp() override {
    hoh = validHohMesh();
    ASSERT_TRUE(hoh.valid) << hoh.problem;
    base = computeMeshQuality(hoh.mesh, {.everyBlock = true});
    ASSERT_TRUE(base.valid) << base.problem;
  }
  HohMesh hoh;
  MeshQuality base;
  static constexpr int oBlock = 1;
};

}  // namespace

TEST_F(HohQuality, ValuesAreInRangeAndTheWorkspaceGivesTheSame) {
  EXPECT_GT(base.QJmin, 0);
  EXPECT_LE(base.QJmin, base.QJavg);
  EXPECT_LE(base.QJavg, 1);
  EXPECT_GT(base.QSmin, 0);
  EXPECT_LE(base.QSmin, base.QSavg);
  EXPECT_LE(base.QSavg, 1);
  EXPECT_EQ(base.Q, (base.QJmin + base.QJavg + base.QSmin + base.QSavg) / 4);
  EXPECT_EQ(base.worstQJ.block, oBlock);
  EXPECT_EQ(base.blocks[oBlock].QJmin, base.QJmin);
  MeshQualityWorkspace w;
  for (int repeat = 0; repeat < 2; ++repeat) {
    const MeshQuality again = computeMeshQuality(hoh.mesh, w);
    EXPECT_EQ(again.Q, base.Q);
    EXPECT_EQ(again.worstQS.i, base.worstQS.i);
    EXPECT_EQ(again.worstQS.j, base.worstQS.j);
  }
}

TEST_F(HohQuality, SameAfterACgnsRoundTrip) {
  const auto file = tempFolder("meshQuality") / "passage.cgns";
  writeCgns(hoh.mesh, file);
  const MeshQuality q = computeMeshQuality(readCgns(file));
  ASSERT_TRUE(q.valid) << q.problem;
  EXPECT_NEAR(q.Q, base.Q, 1e-12);
  EXPECT_NEAR(q.QJmin, base.QJmin, 1e-12);
  EXPECT_EQ(q.worstQJ.i, base.worstQJ.i);
  EXPECT_EQ(q.worstQJ.j, base.worstQJ.j);
}

TEST_F(HohQuality, InvariantUnderTranslationRotationAndScaling) {
  const Eigen::Rotation2Dd rotation(0.7);
  const double scale = 3.7;
  const Eigen::Vector2d shift(12.5, -4.25);
  StructuredMesh moved = hoh.mesh;
  for (auto& b : moved.blocks)
    for (std::size_t n = 0; n < b.x.size(); ++n) {
      const Eigen::Vector2d p = scale * (rotation * Eigen::Vector2d(b.x[n], b.y[n])) + shift;
      b.x[n] = p.x();
      b.y[n] = p.y();
    }
  for (auto& c : moved.connections) c.translation = scale * (rotation * c.translation);
  const MeshQuality q = computeMeshQuality(moved);
  ASSERT_TRUE(q.valid) << q.problem;
  EXPECT_NEAR(q.Q, base.Q, 1e-12);
  EXPECT_NEAR(q.QJmin, base.QJmin, 1e-12);
  EXPECT_NEAR(q.QJavg, base.QJavg, 1e-12);
  EXPECT_NEAR(q.QSmin, base.QSmin, 1e-12);
  EXPECT_NEAR(q.QSavg, base.QSavg, 1e-12);
}

TEST_F(HohQuality, PeriodicImageIsTheNeighbourAcrossAPeriodicSegment) {
  // Move the node one row inside the upper periodic segment; across the lower segment it
  // is (moved by -pitch) the ghost of the facing outer node.
  const BlockConnection& periodic = connectionNamed(hoh.mesh, "oBlockPeriodic");
  const int k = 3;
  const int iLower = rangeNode(periodic.a, k)[0], iUpper = rangeNode(periodic.b, k)[0];
  StructuredMesh mesh = hoh.mesh;
  StructuredBlock& o = mesh.blocks[oBlock];
  const int J = o.nj - 1;
  const Eigen::Vector2d inside = nodeOf(o, iUpper, J - 1);
  const Eigen::Vector2d moved =
      inside + 0.05 * (nodeOf(o, iUpper + 1, J - 1) - inside) + 0.05 * (nodeOf(o, iUpper, J) - inside);
  moveNode(o, iUpper, J - 1, moved);

  MeshQualityWorkspace w;
  const MeshQuality q = computeMeshQuality(mesh, w, {.everyBlock = true});
  ASSERT_TRUE(q.valid) << q.problem;
  const MeshQuality jOnly = computeMeshQuality(mesh, w);  // leaves the O-block's J in w
  EXPECT_EQ(jOnly.Q, q.Q);

  // By hand: the outer node of the lower segment, ghost = moved - translation.
  const Eigen::Vector2d ghost = moved - periodic.translation;
  const Eigen::Vector2d xi = (nodeOf(o, iLower + 1, J) - nodeOf(o, iLower - 1, J)) / 2;
  const Eigen::Vector2d eta = (ghost - nodeOf(o, iLower, J - 1)) / 2;
  EXPECT_NEAR(w.jacobian[static_cast<std::size_t>(iLower + o.ni * J)], jacobianOf(xi, eta),
              1e-12 * std::abs(jacobianOf(xi, eta)));
  // The lower segment's node J changes (the neighbour is used; the cells' Q_J change with
  // it only where that corner is their smallest or largest) ...
  MeshQualityWorkspace unmoved;
  computeMeshQuality(hoh.mesh, unmoved);
  const auto lowerNode = static_cast<std::size_t>(iLower + o.ni * J);
  EXPECT_GT(std::abs(w.jacobian[lowerNode] - unmoved.jacobian[lowerNode]),
            1e-3 * std::abs(unmoved.jacobian[lowerNode]));
  // ... and only cells around the nodes whose J uses the moved node can: its four O-block
  // neighbours and the lower segment's outer node.
  std::set<std::pair<int, int>> affected;
  for (const auto& [i, j] : {std::pair{iUpper - 1, J - 1}, std::pair{iUpper + 1, J - 1},
                             std::pair{iUpper, J - 2}, std::pair{iUpper, J}, std::pair{iLower, J}})
    addCellsAround(o, i, j, affected);
  expectOnlyAffectedCellsChange(o, w.jacobian, base.cellQJ[oBlock], q.cellQJ[oBlock], affected);
}

TEST_F(HohQuality, HBlockNodeIsTheNeighbourAcrossAnInterface) {
  const BlockConnection& inlet = connectionNamed(hoh.mesh, "inletInterface");
  ASSERT_EQ(inlet.a.block, 0);
  const int k = 2;
  const auto h = rangeNode(inlet.a, k);  // on the H-block's last column
  const int iOuter = rangeNode(inlet.b, k)[0];
  StructuredMesh mesh = hoh.mesh;
  StructuredBlock& hIn = mesh.blocks[0];
  const StructuredBlock& o = mesh.blocks[oBlock];
  const int J = o.nj - 1;
  const Eigen::Vector2d moved = nodeOf(hIn, h[0] - 1, h[1]) + Eigen::Vector2d(-0.02, 0.03) *
                                                                    (hIn.yAt(0, 1) - hIn.yAt(0, 0));
  moveNode(hIn, h[0] - 1, h[1], moved);

  MeshQualityWorkspace w;
  const MeshQuality q = computeMeshQuality(mesh, w, {.everyBlock = true});
  ASSERT_TRUE(q.valid) << q.problem;
  computeMeshQuality(mesh, w);
  const Eigen::Vector2d xi = (nodeOf(o, iOuter + 1, J) - nodeOf(o, iOuter - 1, J)) / 2;
  const Eigen::Vector2d eta = (moved - nodeOf(o, iOuter, J - 1)) / 2;
  EXPECT_NEAR(w.jacobian[static_cast<std::size_t>(iOuter + o.ni * J)], jacobianOf(xi, eta),
              1e-12 * std::abs(jacobianOf(xi, eta)));
  std::set<std::pair<int, int>> affected;
  addCellsAround(o, iOuter, J, affected);
  bool someChanged = false;
  for (const auto& [i, j] : affected) {
    const auto cell = static_cast<std::size_t>(i + (o.ni - 1) * j);
    someChanged = someChanged || q.cellQJ[oBlock][cell] != base.cellQJ[oBlock][cell];
  }
  EXPECT_TRUE(someChanged);
  expectOnlyAffectedCellsChange(o, w.jacobian, base.cellQJ[oBlock], q.cellQJ[oBlock], affected);
}

TEST_F(HohQuality, SeamWrapsBladeAndCornersAreOneSided) {
  MeshQualityWorkspace w;
  computeMeshQuality(hoh.mesh, w);
  const StructuredBlock& o = hoh.mesh.blocks[oBlock];
  const int J = o.nj - 1, last = o.ni - 1;
  auto jacobianAt = [&](int i, int j) { return w.jacobian[static_cast<std::size_t>(i + o.ni * j)]; };
  // The seam: i = 0 and i = ni - 1 are one node with neighbours i = 1 and i = ni - 2.
  for (int j = 0; j <= J; ++j) EXPECT_EQ(jacobianAt(0, j), jacobianAt(last, j)) << j;
  const Eigen::Vector2d seamXi = (nodeOf(o, 1, 3) - nodeOf(o, last - 1, 3)) / 2;
  const Eigen::Vector2d seamEta = (nodeOf(o, 0, 4) - nodeOf(o, 0, 2)) / 2;
  EXPECT_NEAR(jacobianAt(0, 3), jacobianOf(seamXi, seamEta), 1e-12 * jacobianAt(0, 3));
  // The blade: one-sided second-order in eta.
  const int i = 40;
  const Eigen::Vector2d bladeXi = (nodeOf(o, i + 1, 0) - nodeOf(o, i - 1, 0)) / 2;
  const Eigen::Vector2d bladeEta =
      (-3 * nodeOf(o, i, 0) + 4 * nodeOf(o, i, 1) - nodeOf(o, i, 2)) / 2;
  EXPECT_NEAR(jacobianAt(i, 0), jacobianOf(bladeXi, bladeEta), 1e-12 * jacobianAt(i, 0));
  // A corner where the inlet interface meets the lower periodic segment: one-sided.
  const int corner = connectionNamed(hoh.mesh, "inletInterface").b.begin[0];
  ASSERT_EQ(corner, connectionNamed(hoh.mesh, "oBlockPeriodic").a.end[0]);
  const Eigen::Vector2d cornerXi = (nodeOf(o, corner + 1, J) - nodeOf(o, corner - 1, J)) / 2;
  const Eigen::Vector2d cornerEta =
      (3 * nodeOf(o, corner, J) - 4 * nodeOf(o, corner, J - 1) + nodeOf(o, corner, J - 2)) / 2;
  EXPECT_NEAR(jacobianAt(corner, J), jacobianOf(cornerXi, cornerEta),
              1e-12 * std::abs(jacobianAt(corner, J)));
}

TEST_F(HohQuality, FoldedCellGivesTheInvalidValue) {
  StructuredMesh mesh = hoh.mesh;
  StructuredBlock& o = mesh.blocks[oBlock];
  // Push a node past its neighbour along j: the cells between them turn inside out.
  const int i = 50, j = 10;
  moveNode(o, i, j, nodeOf(o, i, j + 1) + (nodeOf(o, i, j + 1) - nodeOf(o, i, j)));
  const MeshQuality q = computeMeshQuality(mesh);
  EXPECT_FALSE(q.valid);
  EXPECT_EQ(q.Q, invalidMeshQuality);
  EXPECT_LT(q.Q, 0);
  EXPECT_NE(q.problem.find("OBlock cell"), std::string::npos) << q.problem;
}

TEST_F(HohQuality, NeighboursReadFromTheConnections) {
  OBlockNeighbours n;
  findOBlockNeighbours(hoh.mesh, n);
  EXPECT_EQ(n.oBlock, oBlock);
  EXPECT_TRUE(n.wrapI);
  const StructuredBlock& o = hoh.mesh.blocks[oBlock];
  ASSERT_EQ(n.outer.size(), static_cast<std::size_t>(o.ni));
  const int J = o.nj - 1;
  // Across the periodic segments: the node one row inside the opposite segment, moved
  // by the translation into this side's frame.
  const BlockConnection& periodic = connectionNamed(hoh.mesh, "oBlockPeriodic");
  const int k = 3;
  const int iLower = rangeNode(periodic.a, k)[0], iUpper = rangeNode(periodic.b, k)[0];
  const OuterNeighbour& lower = n.outer[static_cast<std::size_t>(iLower)];
  EXPECT_EQ(lower.block, oBlock);
  EXPECT_EQ(lower.node, iUpper + o.ni * (J - 1));
  EXPECT_EQ(Eigen::Vector2d(lower.dx, lower.dy), -periodic.translation);
  const OuterNeighbour& upper = n.outer[static_cast<std::size_t>(iUpper)];
  EXPECT_EQ(upper.node, iLower + o.ni * (J - 1));
  EXPECT_EQ(Eigen::Vector2d(upper.dx, upper.dy), periodic.translation);
  // Across an interface: the H-block's node one step into it, untranslated.
  const BlockConnection& inlet = connectionNamed(hoh.mesh, "inletInterface");
  const auto h = rangeNode(inlet.a, 2);
  const OuterNeighbour& interface = n.outer[static_cast<std::size_t>(rangeNode(inlet.b, 2)[0])];
  EXPECT_EQ(interface.block, inlet.a.block);
  EXPECT_EQ(interface.node, h[0] - 1 + hoh.mesh.blocks[inlet.a.block].ni * h[1]);
  EXPECT_EQ(interface.dx, 0.0);
  EXPECT_EQ(interface.dy, 0.0);
  // A corner (joined to two faces) has none.
  EXPECT_EQ(n.outer[static_cast<std::size_t>(inlet.b.begin[0])].block, -1);
}

TEST_F(HohQuality, NeighboursRefuseConnectedRangesOfDifferentLengths) {
  StructuredMesh mesh = hoh.mesh;
  for (BlockConnection& c : mesh.connections)
    if (c.name == "oBlockPeriodic") c.b.end[0] += c.b.end[0] > c.b.begin[0] ? -1 : 1;  // one node short
  OBlockNeighbours n;
  EXPECT_THROW(findOBlockNeighbours(mesh, n), std::invalid_argument);
}

// (The values and the worst cells, read back through checkMeshQuality:
// CheckMeshQualityCommand.ReportsQualityAndAddsCellFields.)
TEST_F(HohQuality, XmlReportNamesItsSourceAndEveryBlock) {
  const std::string xml = formatMeshQualityXml(hoh.mesh, base, "mesh/passage.cgns");
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(xml.c_str()), tinyxml2::XML_SUCCESS) << xml;
  const tinyxml2::XMLElement* root = doc.FirstChildElement("meshQuality");
  ASSERT_NE(root, nullptr);
  EXPECT_STREQ(root->Attribute("source"), "mesh/passage.cgns");
  const tinyxml2::XMLElement* list = root->FirstChildElement("blocks");
  ASSERT_NE(list, nullptr) << xml;
  int blocks = 0;
  for (const tinyxml2::XMLElement* b = list->FirstChildElement("block"); b;
       b = b->NextSiblingElement("block"), ++blocks) {
    const auto k = static_cast<std::size_t>(blocks);
    EXPECT_STREQ(b->Attribute("name"), hoh.mesh.blocks[k].name.c_str());
    EXPECT_EQ(std::strtod(b->FirstChildElement("QSmin")->GetText(), nullptr), base.blocks[k].QSmin);
  }
  EXPECT_EQ(blocks, static_cast<int>(hoh.mesh.blocks.size()));
}

TEST(MeshQualityReport, AFileThatIsNotCgnsIsAnInputErrorNamingIt) {
  const auto file = testData::writeTempFile("qualityReport", "notCgns.cgns", "not a CGNS file\n");
  try {
    readMeshWithQuality(file);
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}
