#include "passageMesh/passage/PassageBoundary.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../blade/BladeTestData.hpp"
#include "PassageTestData.hpp"

using namespace passageMesh;

namespace {

PassageCondition condition(double chord) { return testData::paperCondition(chord); }

MeshingParameters parameters(double chord) {
  MeshingParameters m;
  m.yIn = 0.1 * chord;
  m.yOut = -0.2 * chord;
  m.alphaCamber = 0.7;
  m.betaIn = 0.4;
  m.betaOut = 0.6;
  return m;
}

// The paper's formula, for blades with y_le far from y_te.
double paperLowerY(const BladeShape& blade, const PassageCondition& c, const MeshingParameters& m,
                   double x) {
  const double yle = blade.leadingEdge().y(), yte = blade.trailingEdge().y();
  const double xle = blade.leadingEdge().x(), xte = blade.trailingEdge().x();
  const double yc = (yle + m.yIn - yte - m.yOut) / (yle - yte) * blade.camberY(x) +
                    (yle * m.yOut - yte * m.yIn) / (yle - yte) - c.pitch / 2;
  const double yl = yle + m.yIn - c.pitch / 2 +
                    (yte + m.yOut - yle - m.yIn) * (x - xle) / (xte - xle);
  return m.alphaCamber * yc + (1 - m.alphaCamber) * yl;
}

// Half-widths of the fillets at the leading and trailing edge (PassageBoundary.hpp).
struct FilletWindows {
  double leading, trailing;
};
FilletWindows filletWindows(const BladeShape& blade, const PassageBoundary& b) {
  const double xle = blade.leadingEdge().x(), xte = blade.trailingEdge().x();
  const double limit = std::min(0.2 * blade.parameters().chord, 0.25 * (xte - xle));
  return {std::min(limit, 0.5 * (xle - b.inletInterfaceX())),
          std::min(limit, 0.5 * (b.outletInterfaceX() - xte))};
}

}  // namespace

TEST(PassageBoundary, FollowsThePaperFormulaForAStaggeredBlade) {
  const BladeShape blade(testData::typicalTurbineBlade());  // y_le - y_te = 0.64 chord
  const double C = blade.parameters().chord;
  const auto c = condition(C);
  const auto m = parameters(C);
  const PassageBoundary boundary(blade, c, m);
  const double xle = blade.leadingEdge().x(), xte = blade.trailingEdge().x();
  const FilletWindows w = filletWindows(blade, boundary);
  for (int k = 1; k < 50; ++k) {
    const double x = xle + (xte - xle) * k / 50.0;
    if (x < xle + w.leading || x > xte - w.trailing) continue;  // the fillets: below
    // The blend weight w = D^2/(D^2 + d^2) is 0.994 here: agree to 1 % of the offsets.
    EXPECT_NEAR(boundary.lowerY(x), paperLowerY(blade, c, m, x), 0.01 * 0.3 * C) << x;
    EXPECT_DOUBLE_EQ(boundary.upperY(x), boundary.lowerY(x) + c.pitch);
  }
  EXPECT_DOUBLE_EQ(boundary.lowerY(xle - 0.3 * C), blade.leadingEdge().y() + m.yIn - c.pitch / 2);
  EXPECT_DOUBLE_EQ(boundary.lowerY(xte + 0.3 * C), blade.trailingEdge().y() + m.yOut - c.pitch / 2);
  EXPECT_DOUBLE_EQ(boundary.inletX(), xle - c.xIn);
  EXPECT_DOUBLE_EQ(boundary.inletInterfaceX(), xle - m.betaIn * c.xIn);
  EXPECT_DOUBLE_EQ(boundary.outletInterfaceX(), xte + m.betaOut * c.xOut);
}

TEST(PassageBoundary, IsContinuousAndFiniteWhenEdgesAreLevel) {
  // An impulse blade: stagger 0, so y_le == y_te exactly and the paper's formula divides
  // by zero.
  BladeParameters p = testData::typicalTurbineBlade();
  p.stagger = 0;
  p.thetaLe = 45;
  p.thetaTe = -45;
  const BladeShape blade(p);
  ASSERT_EQ(blade.leadingEdge().y(), blade.trailingEdge().y());
  const double C = p.chord;
  const auto c = condition(C);
  const auto m = parameters(C);
  const PassageBoundary boundary(blade, c, m);
  const double xle = blade.leadingEdge().x(), xte = blade.trailingEdge().x();
  const FilletWindows w = filletWindows(blade, boundary);
  const double eps = 1e-9 * C;
  EXPECT_NEAR(boundary.lowerY(xle + eps), boundary.lowerY(xle - eps), 1e-6 * C);
  EXPECT_NEAR(boundary.lowerY(xte - eps), boundary.lowerY(xte + eps), 1e-6 * C);
  for (int k = 0; k <= 100; ++k) {
    const double x = xle + (xte - xle) * k / 100.0;
    const double y = boundary.lowerY(x);
    ASSERT_TRUE(std::isfinite(y));
    if (x < xle + w.leading || x > xte - w.trailing) continue;  // the fillets
    // Here s is linear in x: the boundary is the camber line shifted by an offset going
    // linearly from yIn to yOut, blended with the straight line.
    const double s = (xte - x) / (xte - xle);
    const double yc = blade.camberY(x) + m.yIn * s + m.yOut * (1 - s) - c.pitch / 2;
    const double yl = blade.leadingEdge().y() + m.yIn * s + m.yOut * (1 - s) - c.pitch / 2;
    EXPECT_NEAR(y, m.alphaCamber * yc + (1 - m.alphaCamber) * yl, 1e-12 * C);
  }
}

TEST(PassageBoundary, AlphaZeroIsTheStraightLine) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double C = blade.parameters().chord;
  auto m = parameters(C);
  m.alphaCamber = 0;
  const auto c = condition(C);
  const PassageBoundary boundary(blade, c, m);
  const FilletWindows w = filletWindows(blade, boundary);
  // Between the fillets: the straight line from (x_le, y_le + yIn - pitch/2) to
  // (x_te, y_te + yOut - pitch/2).
  const double xle = blade.leadingEdge().x(), xte = blade.trailingEdge().x();
  const double yA = blade.leadingEdge().y() + m.yIn - c.pitch / 2;
  const double yB = blade.trailingEdge().y() + m.yOut - c.pitch / 2;
  const double xa = xle + w.leading, xb = xte - w.trailing;
  for (double f : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const double x = xa + f * (xb - xa);
    EXPECT_NEAR(boundary.lowerY(x), yA + (yB - yA) * (x - xle) / (xte - xle), 1e-12 * C) << f;
  }
}

// The paper's curve has slope kinks at the edges; the fillets remove them (C1 everywhere
// between the interfaces), lie on the concave side of each kink, and leave the boundary
// flat and exact next to the interfaces.
TEST(PassageBoundary, FilletsMakeTheBoundarySmoothAtTheEdges) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double C = blade.parameters().chord;
  const auto c = condition(C);
  const auto m = parameters(C);
  const PassageBoundary boundary(blade, c, m);
  const double xle = blade.leadingEdge().x(), xte = blade.trailingEdge().x();
  const FilletWindows w = filletWindows(blade, boundary);
  ASSERT_GT(w.leading, 0.05 * C);
  ASSERT_GT(w.trailing, 0.05 * C);
  // No slope jump: neighbouring difference quotients differ by curvature x step only.
  const double h = 1e-5 * C, xA = boundary.inletInterfaceX(), xB = boundary.outletInterfaceX();
  double largestJump = 0;
  for (double x = xA + h; x + 2 * h < xB; x += h) {
    const double left = (boundary.lowerY(x) - boundary.lowerY(x - h)) / h;
    const double right = (boundary.lowerY(x + h) - boundary.lowerY(x)) / h;
    largestJump = std::max(largestJump, std::abs(right - left));
  }
  EXPECT_LT(largestJump, 0.01);
  // The paper's curve does jump in slope at both edges: the test sees a kink when there is one.
  auto paperAt = [&](double x) {  // the paper's curve, flat parts included
    if (x < xle) return blade.leadingEdge().y() + m.yIn - c.pitch / 2;
    if (x >= xte) return blade.trailingEdge().y() + m.yOut - c.pitch / 2;
    return paperLowerY(blade, c, m, x);
  };
  for (double xk : {xle, xte}) {
    const double jump = (paperAt(xk + h) - paperAt(xk)) / h - (paperAt(xk) - paperAt(xk - h)) / h;
    EXPECT_GT(std::abs(jump), 0.1) << xk;
    // Slope rising across the kink (a valley): the fillet lies above the kink; falling
    // (a ridge): below.
    const double offset = boundary.lowerY(xk) - paperAt(xk);
    EXPECT_GT(jump > 0 ? offset : -offset, 1e-4 * C) << xk;
  }
  // Flat and exact between each interface and its fillet.
  EXPECT_DOUBLE_EQ(boundary.lowerY(xA), blade.leadingEdge().y() + m.yIn - c.pitch / 2);
  EXPECT_DOUBLE_EQ(boundary.lowerY(xle - w.leading - h), boundary.lowerY(xA));
  EXPECT_DOUBLE_EQ(boundary.lowerY(xB), blade.trailingEdge().y() + m.yOut - c.pitch / 2);
  EXPECT_DOUBLE_EQ(boundary.lowerY(xte + w.trailing + h), boundary.lowerY(xB));
}

TEST(BladeShape, CamberYInvertsTheCamberLine) {
  const BladeShape blade(testData::typicalTurbineBlade());
  for (double u : {0.0, 0.1, 0.5, 0.93, 1.0}) {
    const Eigen::Vector2d c = blade.camberPoint(u);
    EXPECT_NEAR(blade.camberY(c.x()), c.y(), 1e-12);
  }
}

TEST(PassageBoundary, ClearanceIsTheRoomBetweenBladeAndOuterLoop) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double C = blade.parameters().chord;
  auto c = condition(C);
  MeshingParameters m;  // periodic boundaries along the camber line, midway between blades
  const double roomy = bladeClearance(blade, PassageBoundary(blade, c, m));
  EXPECT_GT(roomy, 0.05 * C);
  EXPECT_LT(roomy, 0.5 * c.pitch);
  // The outlet interface through the trailing-edge point (xOut = 0) cuts the rounded edge
  // behind it: no room, by about the edge's radius (under 2 % of the chord).
  c.xOut = 0;
  const double cut = bladeClearance(blade, PassageBoundary(blade, c, m));
  EXPECT_LT(cut, -0.001 * C);
  EXPECT_GT(cut, -0.02 * C);
  // The inlet interface moved towards the leading edge: the clearance there is its
  // distance from the leading edge, as long as that is the smallest.
  c = condition(C);
  m.betaIn = 0.01 / (c.xIn / C);  // 0.01 chord upstream of the leading edge
  const double nearInlet = bladeClearance(blade, PassageBoundary(blade, c, m));
  EXPECT_GT(nearInlet, 0.0);
  EXPECT_LE(nearInlet, 0.01 * C * (1 + 1e-9));
  // A periodic boundary pushed through the blade: negative.
  c = condition(C);
  m = MeshingParameters{};
  m.yIn = 0.6 * c.pitch;
  m.yOut = 0.6 * c.pitch;
  EXPECT_LT(bladeClearance(blade, PassageBoundary(blade, c, m)), 0.0);
}

TEST(PassageBoundary, WidestYExtentIsThePitchBelowWhichNoBoundaryClearsTheBlade) {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double C = blade.parameters().chord;
  const BladeYExtent widest = widestYExtent(blade);
  // Checked against a profile sampled ten times as densely, at the same x.
  const auto dense = blade.sampleLoop(20000);
  double low = 1e9, high = -1e9;
  for (std::size_t k = 0; k < dense.size(); ++k) {
    const Eigen::Vector2d& a = dense[k];
    const Eigen::Vector2d& b = dense[(k + 1) % dense.size()];
    if ((a.x() - widest.x) * (b.x() - widest.x) > 0 || a.x() == b.x()) continue;
    const double y = a.y() + (widest.x - a.x()) / (b.x() - a.x()) * (b.y() - a.y());
    low = std::min(low, y);
    high = std::max(high, y);
  }
  EXPECT_NEAR(widest.extent, high - low, 1e-6 * C);
  EXPECT_GT(widest.extent, 0.1 * C);  // a staggered, cambered blade: wider in y than thick
  // Moving the blade does not change it; scaling it scales it.
  BladeParameters moved = blade.parameters();
  moved.xLe += 0.3;
  moved.yLe -= 0.7;
  EXPECT_NEAR(widestYExtent(BladeShape(moved)).extent, widest.extent, 1e-9 * C);
  EXPECT_NEAR(widestYExtent(BladeShape(moved)).x, widest.x + 0.3, 1e-9 * C);
  BladeParameters scaled = blade.parameters();
  scaled.chord *= 2;
  scaled.xLe *= 2;
  scaled.yLe *= 2;
  EXPECT_NEAR(widestYExtent(BladeShape(scaled)).extent, 2 * widest.extent, 1e-9 * C);
  auto bestClearance = [&](double pitch) {
    PassageCondition c = condition(C);
    c.pitch = pitch;
    double best = -1e9;
    for (int yIn = -5; yIn <= 5; ++yIn)
      for (int yOut = -5; yOut <= 5; ++yOut)
        for (int alpha = 0; alpha <= 4; ++alpha) {
          MeshingParameters m;
          m.yIn = 0.1 * yIn * C;
          m.yOut = 0.1 * yOut * C;
          m.alphaCamber = 0.25 * alpha;
          best = std::max(best, bladeClearance(blade, PassageBoundary(blade, c, m)));
        }
    return best;
  };
  // Just below it no boundary in the parameter box (yIn, yOut, alphaCamber) clears the
  // blade; well above it one does.
  EXPECT_LT(bestClearance(0.99 * widest.extent), 0.0);
  EXPECT_GT(bestClearance(1.5 * widest.extent), 0.0);
}
