#include "passageMesh/mesh/HohMesh.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "passageMesh/mesh/BladeNodes.hpp"
#include "passageMesh/mesh/OuterLoop.hpp"
#include "passageMesh/mesh/Stretching.hpp"
#include "passageMesh/passage/PassageBoundary.hpp"

namespace passageMesh {

namespace {

StructuredBlock makeBlock(const std::string& name, int ni, int nj) {
  StructuredBlock b;
  b.name = name;
  b.ni = ni;
  b.nj = nj;
  b.x.assign(static_cast<std::size_t>(ni) * nj, 0.0);
  b.y.assign(static_cast<std::size_t>(ni) * nj, 0.0);
  return b;
}

// A wall-normal line from wall node `b` (unit outward normal `n`) to outer node `o`:
// a cubic Hermite curve leaving along n and arriving along o - b, with nodes at the
// wall-clustered arc lengths. Writes nodes j = 0..nN-1 of column i.
// Node j = 1 sits exactly firstCellHeight along `wallNormal` (the wall normal); the curve
// beyond it leaves along the smoothed direction `n`.
void fillNormalLine(StructuredBlock& block, int i, const Eigen::Vector2d& b,
                    const Eigen::Vector2d& wallNormal, const Eigen::Vector2d& n,
                    const Eigen::Vector2d& o, double firstCellHeight) {
  const double chord = (o - b).norm();
  const Eigen::Vector2d t0 = n * chord * 0.4, t1 = o - b;
  auto curve = [&](double t) {
    const double t2 = t * t, t3 = t2 * t;
    return Eigen::Vector2d((2 * t3 - 3 * t2 + 1) * b + (t3 - 2 * t2 + t) * t0 +
                           (-2 * t3 + 3 * t2) * o + (t3 - t2) * t1);
  };
  constexpr int samples = 400;
  std::vector<double> s(samples + 1, 0.0), ts(samples + 1, 0.0);
  Eigen::Vector2d last = b;
  for (int k = 1; k <= samples; ++k) {
    // Denser samples near the wall, where the first node must land exactly.
    ts[k] = std::pow(static_cast<double>(k) / samples, 2.0);
    const Eigen::Vector2d p = curve(ts[k]);
    s[k] = s[k - 1] + (p - last).norm();
    last = p;
  }
  const auto distances = wallClusteredDistances(block.nj, s.back(), firstCellHeight);
  std::size_t k = 1;
  for (int j = 0; j < block.nj; ++j) {
    Eigen::Vector2d p;
    if (j == 0) {
      p = b;
    } else if (j == block.nj - 1) {
      p = o;
    } else if (j == 1) {
      p = b + firstCellHeight * wallNormal;  // exact first cell height, orthogonal
    } else {
      while (k < s.size() - 1 && s[k] < distances[j]) ++k;
      const double f = (distances[j] - s[k - 1]) / (s[k] - s[k - 1]);
      p = curve(ts[k - 1] + f * (ts[k] - ts[k - 1]));
    }
    block.xAt(i, j) = p.x();
    block.yAt(i, j) = p.y();
  }
}

// The blade must lie strictly between the periodic boundaries. Large yIn or yOut, or a
// small alphaCamber at a small pitch, make one of them cut through the blade: then no
// mesh exists, and saying so here is clearer (and cheaper) than the folded cells or the
// diverging smoother it would otherwise end in.
std::string periodicBoundaryCrossing(const PassageBoundary& boundary,
                                     const std::vector<BladeNode>& wall) {
  for (const auto& node : wall) {
    const double x = node.point.x(), y = node.point.y();
    if (x < boundary.inletInterfaceX() || x > boundary.outletInterfaceX()) continue;
    const bool below = y <= boundary.lowerY(x), above = y >= boundary.upperY(x);
    if (below || above) {
      char where[64];
      std::snprintf(where, sizeof where, "%.6g m", x);
      return std::string("the ") + (below ? "lower" : "upper") +
             " periodic boundary cuts the blade at x = " + where +
             " (yIn, yOut or alphaCamber too far from the camber line for this pitch)";
    }
  }
  return "";
}

}  // namespace

HohMesh buildHohMesh(const BladeShape& blade, const PassageCondition& condition,
                     const MeshingParameters& parameters, const HohMeshOptions& options) {
  const int nT = parameters.nT;
  if (nT < 8) throw std::invalid_argument("buildHohMesh: nT must be at least 8");
  HohMesh result;
  result.nN = std::max(2, static_cast<int>(std::lround(static_cast<double>(condition.nO) / nT)));
  const PassageBoundary boundary(blade, condition, parameters);

  const auto wall = distributeBladeNodes(blade, nT, parameters.gammaLe, parameters.gammaTe);
  result.problem = periodicBoundaryCrossing(boundary, wall);
  if (!result.problem.empty()) return result;
  int lowerIntervals = 0;
  while (wall[static_cast<std::size_t>(lowerIntervals)].side == BladeSide::lower) ++lowerIntervals;
  OuterLoop outer;
  try {
    outer = buildOuterLoop(boundary, nT, lowerIntervals, blade.leadingEdge().y(),
                           blade.trailingEdge().y());
  } catch (const std::invalid_argument& e) {
    result.problem = e.what();
    return result;
  }

  // Line directions: the wall normals smoothed around the loop. Where the normal turns
  // fast (a small trailing-edge radius with few nodes) the raw normals cross a short way
  // out and fold the cells; smoothed ones fan out instead (method.md section 4).
  std::vector<Eigen::Vector2d> direction(nT), firstRowDirection(nT);
  for (int i = 0; i < nT; ++i) direction[i] = wall[i].outwardNormal;
  // The first row (j = 1) leaves along the normal smoothed twice only: orthogonal to the
  // wall to within a degree except at the sharpest edges, where the raw normals of SIRT's
  // trailing edge (radius about 2 firstCellHeight) already fold the second cell.
  constexpr int firstRowPasses = 2;
  for (int pass = 0; pass < 20; ++pass) {
    if (pass == firstRowPasses) firstRowDirection = direction;
    std::vector<Eigen::Vector2d> next(nT);
    for (int i = 0; i < nT; ++i)
      next[i] = (direction[(i + nT - 1) % nT] + 2 * direction[i] + direction[(i + 1) % nT]).normalized();
    direction.swap(next);
  }

  StructuredMesh& mesh = result.mesh;
  const int nN = result.nN, J = nN - 1;
  StructuredBlock o = makeBlock("OBlock", nT + 1, nN);
  try {
    for (int i = 0; i < nT; ++i)
      fillNormalLine(o, i, wall[i].point, firstRowDirection[i], direction[i], outer.nodes[i],
                     condition.firstCellHeight);
  } catch (const std::invalid_argument& e) {
    result.problem = std::string("O-block: ") + e.what();
    return result;
  }
  for (int j = 0; j < nN; ++j) {  // the seam
    o.xAt(nT, j) = o.xAt(0, j);
    o.yAt(nT, j) = o.yAt(0, j);
  }
  if (options.smooth && nN >= 4) {
    result.smoothing = smoothOBlock(o, options.elliptic);
    if (!std::isfinite(result.smoothing.residual)) {
      result.problem = "O-block: the elliptic smoothing diverged";
      return result;
    }
  }

  // H-blocks: uniform cells, their interface nodes copied from the O-block.
  const int inletIntervals = outer.inletLower + outer.inletUpper;
  const int inletBegin = outer.lowerPeriodicEnd();
  const double dyIn = condition.pitch / inletIntervals;
  const double inletLength = boundary.inletInterfaceX() - boundary.inletX();
  const int niIn = 1 + std::max(1, static_cast<int>(std::lround(inletLength / dyIn)));
  StructuredBlock hIn = makeBlock("HInlet", niIn, inletIntervals + 1);
  for (int j = 0; j <= inletIntervals; ++j) {
    const double xI = o.xAt(inletBegin + j, J), yI = o.yAt(inletBegin + j, J);
    for (int i = 0; i < niIn; ++i) {
      hIn.xAt(i, j) = i == niIn - 1 ? xI : boundary.inletX() + inletLength * i / (niIn - 1);
      hIn.yAt(i, j) = yI;
    }
  }
  const int outletIntervals = outer.outletLower + outer.outletUpper;
  const double dyOut = condition.pitch / outletIntervals;
  const double outletLength = boundary.outletX() - boundary.outletInterfaceX();
  const int niOut = 1 + std::max(1, static_cast<int>(std::lround(outletLength / dyOut)));
  StructuredBlock hOut = makeBlock("HOutlet", niOut, outletIntervals + 1);
  for (int j = 0; j <= outletIntervals; ++j) {
    // Bottom corner (O-block i = outletLower) down the O-block's i to the seam, then from
    // i = nT down to the top corner.
    const int io = j <= outer.outletLower ? outer.outletLower - j : nT - (j - outer.outletLower);
    const double xI = o.xAt(io, J), yI = o.yAt(io, J);
    for (int i = 0; i < niOut; ++i) {
      hOut.xAt(i, j) = i == 0 ? xI : xI + outletLength * i / (niOut - 1);
      hOut.yAt(i, j) = yI;
    }
  }
  mesh.blocks = {hIn, o, hOut};

  // Connections and patches (block indices 0 HInlet, 1 OBlock, 2 HOutlet).
  const Eigen::Vector2d pitchUp(0, condition.pitch);
  auto range = [](int block, int i0, int j0, int i1, int j1) {
    return NodeRange{block, {i0, j0}, {i1, j1}};
  };
  const int topIn = inletIntervals, topOut = outletIntervals;
  mesh.connections = {
      {"inletInterface", range(0, niIn - 1, 0, niIn - 1, topIn),
       range(1, inletBegin, J, inletBegin + inletIntervals, J), false, Eigen::Vector2d::Zero()},
      {"outletInterfaceLower", range(2, 0, 0, 0, outer.outletLower),
       range(1, outer.outletLower, J, 0, J), false, Eigen::Vector2d::Zero()},
      {"outletInterfaceUpper", range(2, 0, outer.outletLower, 0, topOut),
       range(1, nT, J, outer.upperPeriodicEnd(), J), false, Eigen::Vector2d::Zero()},
      {"oBlockSeam", range(1, 0, 0, 0, J), range(1, nT, 0, nT, J), false, Eigen::Vector2d::Zero()},
      {"oBlockPeriodic", range(1, outer.lowerPeriodicBegin(), J, outer.lowerPeriodicEnd(), J),
       range(1, outer.upperPeriodicEnd(), J, outer.upperPeriodicBegin(), J), true, pitchUp},
      {"inletPeriodic", range(0, 0, 0, niIn - 1, 0), range(0, 0, topIn, niIn - 1, topIn), true,
       pitchUp},
      {"outletPeriodic", range(2, 0, 0, niOut - 1, 0), range(2, 0, topOut, niOut - 1, topOut),
       true, pitchUp}};
  mesh.patches = {{"blade", PatchType::wall, range(1, 0, 0, nT, 0)},
                  {"inlet", PatchType::inlet, range(0, 0, 0, 0, topIn)},
                  {"outlet", PatchType::outlet, range(2, niOut - 1, 0, niOut - 1, topOut)}};

  result.problem = findInvalidCell(mesh);
  result.valid = result.problem.empty();
  return result;
}

}  // namespace passageMesh
