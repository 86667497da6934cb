// Structure of the HOH mesh: node counts, exact periodic images, point-matched interfaces,
// uniform H-blocks. (Cell validity needs the elliptic smoother: issue 3.)
#include "passageMesh/mesh/HohMesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "../blade/BladeTestData.hpp"
#include "../passage/PassageTestData.hpp"
#include "passageMesh/mesh/MeshStatistics.hpp"
#include "passageMesh/mesh/OuterLoop.hpp"
#include "passageMesh/passage/PassageBoundary.hpp"
#include "passageMesh/passage/PassageSampler.hpp"
#include "passageMesh/structured/CgnsWriter.hpp"

using namespace passageMesh;

using testData::paperCondition;

TEST(OuterLoop, PeriodicNodesAreExactImagesAndCountsAddUp) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double C = blade.parameters().chord;
  MeshingParameters m;
  m.yIn = 0.1 * C;
  m.alphaCamber = 0.6;
  const PassageBoundary boundary(blade, paperCondition(C), m);
  const OuterLoop loop = buildOuterLoop(boundary, 300, 140, blade.leadingEdge().y(),
                                        blade.trailingEdge().y());
  ASSERT_EQ(loop.nodes.size(), 300u);
  EXPECT_EQ(loop.outletLower + 2 * loop.periodic + loop.inletLower + loop.inletUpper +
                loop.outletUpper,
            300);
  for (int k = 0; k <= loop.periodic; ++k) {
    const auto& lower = loop.nodes[loop.lowerPeriodicEnd() - k];
    const auto& upper = loop.nodes[loop.upperPeriodicBegin() + k];
    EXPECT_EQ(lower.x(), upper.x()) << k;
    EXPECT_NEAR(upper.y() - lower.y(), 0.85 * C, 1e-12 * C) << k;
    EXPECT_NEAR(lower.y(), boundary.lowerY(lower.x()), 1e-15);
  }
  EXPECT_EQ(loop.nodes[loop.lowerPeriodicEnd()].x(), boundary.inletInterfaceX());
  EXPECT_EQ(loop.nodes[loop.upperPeriodicEnd() % 300].x(), boundary.outletInterfaceX());
}

TEST(OuterLoop, TheSplitsMoveTheSidesCountsBetweenTheInterfaces) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double C = blade.parameters().chord;
  MeshingParameters m;
  m.alphaCamber = 0.6;
  const PassageBoundary boundary(blade, paperCondition(C), m);
  auto loopWith = [&](double splitIn, double splitOut) {
    return buildOuterLoop(boundary, 300, 140, blade.leadingEdge().y(), blade.trailingEdge().y(),
                          splitIn, splitOut);
  };
  const OuterLoop edges = loopWith(0, 0), moved = loopWith(0.2, -0.2);
  // The outlet split down: the lower side gives outlet nodes to the upper side's outlet
  // piece; the inlet split up: the upper side gives inlet nodes to the lower side's.
  EXPECT_LT(moved.outletLower, edges.outletLower);
  EXPECT_GT(moved.outletUpper, edges.outletUpper);
  EXPECT_GT(moved.inletLower, edges.inletLower);
  EXPECT_LT(moved.inletUpper, edges.inletUpper);
  // The interfaces stay uniform over the whole pitch: the seam node sits where the counts put it.
  const double pitch = boundary.pitch(), yLowB = boundary.lowerY(boundary.outletInterfaceX());
  EXPECT_NEAR(moved.nodes[0].y() - yLowB, pitch * moved.outletLower / (moved.outletLower + moved.outletUpper), 1e-12 * C);
  // To the corners and beyond: every piece keeps a node, the pairs stay exact.
  for (const double split : {-0.5, 0.5}) {
    const OuterLoop extreme = loopWith(split, split);
    EXPECT_GE(std::min({extreme.outletLower, extreme.inletLower, extreme.inletUpper, extreme.outletUpper}), 1) << split;
    EXPECT_EQ(extreme.outletLower + 2 * extreme.periodic + extreme.inletLower + extreme.inletUpper + extreme.outletUpper, 300);
    for (int k = 0; k <= extreme.periodic; ++k)
      EXPECT_EQ(extreme.nodes[extreme.lowerPeriodicEnd() - k].x(), extreme.nodes[extreme.upperPeriodicBegin() + k].x());
  }
}

TEST(OuterLoop, PeriodicSpacingMeetsTheInterfaceSpacingAtTheCorners) {
  // Uniform when the interfaces' spacing is the segment's own.
  const auto uniform = periodicArcPositions(2.0, 80, 2.0 / 80, 2.0 / 80);
  for (int k = 0; k <= 80; ++k) EXPECT_NEAR(uniform[k], 2.0 * k / 80, 1e-15) << k;
  // A finer inlet and a coarser outlet: the end intervals follow them (to the O(1/n^2)
  // of a first difference), the middle stays nearly uniform, the positions increase throughout.
  const double inlet = 0.7 * 2.0 / 80, outlet = 1.3 * 2.0 / 80;
  const auto graded = periodicArcPositions(2.0, 80, inlet, outlet);
  EXPECT_EQ(graded.front(), 0.0);
  EXPECT_EQ(graded.back(), 2.0);
  EXPECT_NEAR(graded[1] - graded[0], inlet, 0.05 * inlet);
  EXPECT_NEAR(graded[80] - graded[79], outlet, 0.05 * outlet);
  EXPECT_NEAR(graded[41] - graded[40], 2.0 / 80, 5e-3 * 2.0 / 80);  // the blends' tails: 0.1 %
  for (int k = 1; k <= 80; ++k) EXPECT_GT(graded[k], graded[k - 1]) << k;
  // Spacings far off the segment's own still give increasing positions (the corrections
  // are clipped at the segment's length).
  const auto extreme = periodicArcPositions(1.0, 10, 1.0, 1e-6);
  for (int k = 1; k <= 10; ++k) EXPECT_GT(extreme[k], extreme[k - 1]) << k;
  EXPECT_THROW(periodicArcPositions(1.0, 0, 0.1, 0.1), std::invalid_argument);
}

TEST(HohMesh, BlocksArePointMatchedAndPeriodic) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double C = blade.parameters().chord;
  const PassageCondition c = paperCondition(C);
  MeshingParameters m = MeshingParameters::defaults(C);
  m.nT = 300;
  const HohMesh hoh = buildHohMesh(blade, c, m);
  ASSERT_EQ(hoh.mesh.blocks.size(), 3u);
  const auto& o = hoh.mesh.blocks[1];
  EXPECT_EQ(o.name, "OBlock");
  EXPECT_EQ(o.ni, 301);  // nT + 1: the seam node repeated
  EXPECT_EQ(o.nj, 100);  // nN = nO / nT = 30000 / 300
  // The writer's checks: ranges on block edges, equal counts, connected nodes coincide
  // (after the pitch for periodic pairs).
  EXPECT_NO_THROW(validateStructuredMesh(hoh.mesh));
  // First cell height exactly along the line direction at every wall node.
  for (int i = 0; i < o.ni; ++i) {
    const double h = std::hypot(o.xAt(i, 1) - o.xAt(i, 0), o.yAt(i, 1) - o.yAt(i, 0));
    EXPECT_NEAR(h, c.firstCellHeight, 1e-12 * C) << i;
  }
  // H-blocks: uniform cells.
  for (int b : {0, 2}) {
    const auto& h = hoh.mesh.blocks[b];
    const double dx = h.xAt(1, 0) - h.xAt(0, 0), dy = h.yAt(0, 1) - h.yAt(0, 0);
    for (int j = 0; j + 1 < h.nj; ++j)
      for (int i = 0; i + 1 < h.ni; ++i) {
        EXPECT_NEAR(h.xAt(i + 1, j) - h.xAt(i, j), dx, 1e-12 * C);
        EXPECT_NEAR(h.yAt(i, j + 1) - h.yAt(i, j), dy, 1e-12 * C);
      }
  }
}

TEST(HohMesh, FindsFoldedCells) {
  StructuredMesh mesh;
  StructuredBlock b;
  b.name = "B";
  b.ni = b.nj = 2;
  b.x = {0, 1, 0, 1};
  b.y = {0, 0, 1, 1};
  mesh.blocks = {b};
  EXPECT_EQ(findInvalidCell(mesh), "");
  mesh.blocks[0].x = {0, 1, 1, 0};  // corners swapped: a bow tie
  EXPECT_NE(findInvalidCell(mesh), "");
}

// A periodic boundary moved far off the camber line at a small pitch cuts through the
// blade: no mesh exists, and the result says which boundary and where, without smoothing.
TEST(HohMesh, SaysWhenAPeriodicBoundaryCutsTheBlade) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double C = blade.parameters().chord;
  PassageCondition c = paperCondition(C);
  c.pitch = 0.3 * C;
  for (double yIn : {0.5 * C, -0.5 * C}) {
    MeshingParameters m = MeshingParameters::defaults(C);
    m.yIn = yIn;
    const HohMesh hoh = buildHohMesh(blade, c, m);
    EXPECT_FALSE(hoh.valid);
    EXPECT_NE(hoh.problem.find(yIn > 0 ? "the lower periodic boundary cuts the blade at x = "
                                       : "the upper periodic boundary cuts the blade at x = "),
              std::string::npos)
        << hoh.problem;
    EXPECT_EQ(hoh.smoothing.iterations, 0);
  }
  // A periodic boundary midway between the camber lines (alphaCamber 1, no offsets) at the
  // same pitch keeps this blade inside. (The defaults since 2026-12-04, alphaCamber 0.98
  // and yOut -0.01 C, cut it at this pitch: docs/benchmarks.md.)
  MeshingParameters midway = MeshingParameters::defaults(C);
  midway.yIn = midway.yOut = 0;
  midway.alphaCamber = 1;
  const HohMesh ok = buildHohMesh(blade, c, midway);
  EXPECT_EQ(ok.problem.find("cuts the blade"), std::string::npos) << ok.problem;
  // The parameters are to blame here, not the pitch.
  EXPECT_EQ(ok.problem.find("overlaps its periodic neighbour"), std::string::npos) << ok.problem;
}

// At a pitch below the blade's extent in y every periodic boundary cuts it: the problem
// says that the cascade cannot exist instead of pointing at the meshing parameters.
TEST(HohMesh, SaysWhenTheBladeOverlapsItsPeriodicNeighbour) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double C = blade.parameters().chord;
  PassageCondition c = paperCondition(C);
  c.pitch = 0.95 * widestYExtent(blade).extent;
  const HohMesh hoh = buildHohMesh(blade, c, MeshingParameters::defaults(C));
  EXPECT_FALSE(hoh.valid);
  EXPECT_NE(hoh.problem.find("periodic boundary cuts the blade at x = "), std::string::npos) << hoh.problem;
  EXPECT_NE(hoh.problem.find("overlaps its periodic neighbour, and no meshing parameters give a passage"),
            std::string::npos)
      << hoh.problem;
  EXPECT_EQ(hoh.problem.find("yIn, yOut or alphaCamber"), std::string::npos) << hoh.problem;
}

// An interface at the edge itself (xOut = 0, or betaIn xIn = 0) cuts the rounded edge:
// no mesh exists either, and the result names the interface.
TEST(HohMesh, SaysWhenAnInterfaceCutsTheBlade) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double C = blade.parameters().chord;
  PassageCondition c = paperCondition(C);
  c.xOut = 0;
  HohMesh hoh = buildHohMesh(blade, c, MeshingParameters::defaults(C));
  EXPECT_FALSE(hoh.valid);
  EXPECT_NE(hoh.problem.find("the outlet interface (x = "), std::string::npos) << hoh.problem;
  EXPECT_EQ(hoh.smoothing.iterations, 0);
  c = paperCondition(C);
  MeshingParameters m = MeshingParameters::defaults(C);
  m.betaIn = 0;
  const HohMeshOptions asked = HohMeshOptions{}.withoutParameterMoves();  // (next tests)
  hoh = buildHohMesh(blade, c, m, asked);
  EXPECT_FALSE(hoh.valid);
  EXPECT_NE(hoh.problem.find("the inlet interface (x = "), std::string::npos) << hoh.problem;
}

// Where the outer loop leaves the blade too little room, the loop is moved away (toward
// the defaults' periodic boundaries and the interfaces' upper bound) just far enough, and
// the mesh is built again; a mesh valid as asked, and a passage cut by a periodic boundary,
// are left as they are.
TEST(HohMesh, MovesTheOuterLoopAwayWhereItLeavesTooLittleRoom) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double C = blade.parameters().chord;
  const PassageCondition c = paperCondition(C);
  MeshingParameters m = MeshingParameters::defaults(C);
  m.betaIn = 0;  // the inlet interface through the leading edge
  m.nT = 200;
  const HohMeshOptions asked = HohMeshOptions{}.withoutParameterMoves();
  const HohMesh cut = buildHohMesh(blade, c, m, asked);
  ASSERT_FALSE(cut.valid);

  const HohMesh hoh = buildHohMesh(blade, c, m);
  ASSERT_TRUE(hoh.valid) << hoh.problem;
  EXPECT_EQ(hoh.firstTryProblem, cut.problem);
  EXPECT_EQ(hoh.parametersMoved.find("betaIn 0 -> "), 0u) << hoh.parametersMoved;
  EXPECT_GT(hoh.parameters.betaIn, 0.0);
  EXPECT_LT(hoh.parameters.betaIn, MeshingParameters::fromArray(MeshingParameters::upperBounds(C)).betaIn);
  // Just far enough: the room asked for, to the bisection's resolution.
  const double room = bladeClearance(blade, PassageBoundary(blade, c, hoh.parameters)) / C;
  EXPECT_GE(room, HohMeshOptions{}.outerLoopRoom);
  EXPECT_LT(room, HohMeshOptions{}.outerLoopRoom + 0.01);
  // Only the outer loop's parameters move.
  EXPECT_EQ(hoh.parameters.nT, m.nT);
  EXPECT_EQ(hoh.parameters.gammaLe, m.gammaLe);
  EXPECT_EQ(hoh.parameters.gammaTe, m.gammaTe);

  const MeshingParameters defaults = MeshingParameters::defaults(C);
  const HohMesh asIs = buildHohMesh(blade, c, defaults);
  ASSERT_TRUE(asIs.valid);
  EXPECT_TRUE(asIs.parametersMoved.empty());
  EXPECT_TRUE(asIs.firstTryProblem.empty());
  EXPECT_EQ(asIs.parameters.toArray(), defaults.toArray());
}

// Draw 389 of the robustness sweep (seed 20261122; nT 163, gammaLE 0.90, gammaTE 0.58):
// the smoothed lines fold at the trailing edge, also with the outer loop moved to 0.1
// chord of room; with the node clustering moved halfway to the defaults' on top, it meshes.
TEST(HohMesh, MovesTheNodeClusteringTowardTheDefaultsWhereTheEdgesFold) {
  const PassageDraw d = samplePassages(500, 20261122)[389];
  const BladeShape blade(d.blade);
  HohMeshOptions without;
  without.clusteringMoves = false;
  const HohMesh folded = buildHohMesh(blade, d.condition, d.parameters, without);
  ASSERT_FALSE(folded.valid);
  EXPECT_NE(folded.problem.find("still invalid"), std::string::npos) << folded.problem;  // the outer loop's move

  const HohMesh hoh = buildHohMesh(blade, d.condition, d.parameters);
  ASSERT_TRUE(hoh.valid) << hoh.problem;
  const MeshingParameters defaults = MeshingParameters::defaults(d.blade.chord);
  EXPECT_DOUBLE_EQ(hoh.parameters.gammaLe, 0.5 * (d.parameters.gammaLe + defaults.gammaLe));
  EXPECT_DOUBLE_EQ(hoh.parameters.gammaTe, 0.5 * (d.parameters.gammaTe + defaults.gammaTe));
  EXPECT_EQ(hoh.parameters.nT, d.parameters.nT);
  EXPECT_NE(hoh.parametersMoved.find("gammaTE "), std::string::npos) << hoh.parametersMoved;
  EXPECT_NE(hoh.parametersMoved.find("node clustering halfway to the defaults'"), std::string::npos)
      << hoh.parametersMoved;
  EXPECT_EQ(hoh.firstTryProblem.find("the smoothed lines fold"), 0u) << hoh.firstTryProblem;
}

// Draw 4 of the robustness sweep (seed 20261122) at the defaults meshes, but with both
// interface splits moved half a pitch (the inlet's down, the outlet's up) its lines fold,
// also with the outer loop and the clustering moved; with the splits halfway back it meshes.
TEST(HohMesh, MovesTheInterfaceSplitsTowardTheDefaultsWhereTheLinesFold) {
  const PassageDraw d = samplePassages(500, 20261122)[4];
  const BladeShape blade(d.blade);
  MeshingParameters p = MeshingParameters::defaults(d.blade.chord);
  ASSERT_TRUE(buildHohMesh(blade, d.condition, p).valid);
  p.splitIn = -0.5;
  p.splitOut = 0.5;
  HohMeshOptions without;
  without.splitMoves = false;
  const HohMesh folded = buildHohMesh(blade, d.condition, p, without);
  ASSERT_FALSE(folded.valid);

  const HohMesh hoh = buildHohMesh(blade, d.condition, p);
  ASSERT_TRUE(hoh.valid) << hoh.problem;
  EXPECT_DOUBLE_EQ(hoh.parameters.splitIn, -0.25);
  EXPECT_DOUBLE_EQ(hoh.parameters.splitOut, 0.25);
  EXPECT_EQ(hoh.parameters.nT, p.nT);
  EXPECT_NE(hoh.parametersMoved.find("splitOut 0.5 -> 0.25"), std::string::npos) << hoh.parametersMoved;
  EXPECT_NE(hoh.parametersMoved.find("interface splits halfway to the defaults'"), std::string::npos)
      << hoh.parametersMoved;
}

// Draw 284 of the robustness sweep (seed 20261122; clearance 0.076 chord; draw 475 was
// this case until the outer loop's counts were rounded once, seventeenth session): the
// wall's orthogonality control crosses the smoothed lines' first rows, with or without the
// outer loop's; the try without the wall's control meshes it, and the rows are still
// placed with the first cell height exact.
TEST(HohMesh, TriesWithoutTheWallsOrthogonalityWhereTheLinesFold) {
  const PassageDraw d = samplePassages(500, 20261122)[284];
  const BladeShape blade(d.blade);
  HohMeshOptions without;
  without.triesWithoutWallOrthogonality = false;
  without.outerLoopRoom = 0;  // (the later tries come first; with them off, moves would)
  without.clusteringMoves = false;
  const HohMesh folded = buildHohMesh(blade, d.condition, d.parameters, without);
  ASSERT_FALSE(folded.valid);
  EXPECT_NE(folded.problem.find("fold"), std::string::npos) << folded.problem;

  const HohMesh hoh = buildHohMesh(blade, d.condition, d.parameters);
  ASSERT_TRUE(hoh.valid) << hoh.problem;
  EXPECT_EQ(hoh.retryWithout, "the wall");
  EXPECT_EQ(hoh.firstTryProblem, folded.problem);
  const WallLayerStatistics wall = wallLayerStatistics(hoh.mesh.blocks[1], d.condition.firstCellHeight);
  EXPECT_GE(wall.heightWithin2Percent, 0.95);
}
