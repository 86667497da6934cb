#include "passageMesh/mesh/HohMesh.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "passageMesh/mesh/BladeNodes.hpp"
#include "passageMesh/mesh/LineRedistribution.hpp"
#include "passageMesh/mesh/MeshStatistics.hpp"  // discreteWallNormal
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

// A line from wall node `b` leaving along direction `n` to outer node `o`: a cubic
// Hermite curve arriving along o - b, with its nodes j = 0 .. nj - 1 of column i evenly
// spaced in arc length (the rows the elliptic equations are solved on).
void fillLine(StructuredBlock& block, int i, const Eigen::Vector2d& b, const Eigen::Vector2d& n,
              const Eigen::Vector2d& o) {
  const double chord = (o - b).norm();
  const Eigen::Vector2d t0 = n * chord * 0.4, t1 = o - b;
  auto curve = [&](double t) {
    const double t2 = t * t, t3 = t2 * t;
    return Eigen::Vector2d((2 * t3 - 3 * t2 + 1) * b + (t3 - 2 * t2 + t) * t0 +
                           (-2 * t3 + 3 * t2) * o + (t3 - t2) * t1);
  };
  constexpr int samples = 400;
  std::vector<double> s(samples + 1, 0.0);
  Eigen::Vector2d last = b;
  for (int k = 1; k <= samples; ++k) {
    const Eigen::Vector2d p = curve(static_cast<double>(k) / samples);
    s[k] = s[k - 1] + (p - last).norm();
    last = p;
  }
  std::size_t k = 1;
  for (int j = 0; j < block.nj; ++j) {
    const double target = s.back() * j / (block.nj - 1);
    while (k < s.size() - 1 && s[k] < target) ++k;
    const double f = (target - s[k - 1]) / (s[k] - s[k - 1]);
    const Eigen::Vector2d p = j == 0 ? b : j == block.nj - 1 ? o : curve((k - 1 + f) / samples);
    block.xAt(i, j) = p.x();
    block.yAt(i, j) = p.y();
  }
}

// Line directions: the wall normals smoothed around the loop. Where the normal turns
// fast (a small trailing-edge radius with few nodes) the raw normals cross a short way
// out and fold the cells; smoothed ones fan out instead (method.md section 4).
std::vector<Eigen::Vector2d> lineDirections(const std::vector<BladeNode>& wall, int passes) {
  const int nT = static_cast<int>(wall.size());
  std::vector<Eigen::Vector2d> direction(wall.size()), next(wall.size());
  for (int i = 0; i < nT; ++i) direction[i] = wall[i].outwardNormal;
  for (int pass = 0; pass < passes; ++pass) {
    for (int i = 0; i < nT; ++i)
      next[i] = (direction[(i + nT - 1) % nT] + 2 * direction[i] + direction[(i + 1) % nT]).normalized();
    direction.swap(next);
  }
  return direction;
}

// Each direction turned back to within `limitDegrees` of the discrete wall normal (the one
// wallLayerStatistics measures against), where it leans further.
std::vector<Eigen::Vector2d> limitedToWallAngle(std::vector<Eigen::Vector2d> direction,
                                                const std::vector<BladeNode>& wall, double limitDegrees) {
  if (limitDegrees <= 0) return direction;
  const int nT = static_cast<int>(wall.size());
  const double limit = limitDegrees * M_PI / 180;
  for (int i = 0; i < nT; ++i) {
    const Eigen::Vector2d normal = discreteWallNormal(wall[(i + nT - 1) % nT].point, wall[(i + 1) % nT].point);
    const Eigen::Vector2d& d = direction[i];
    const double angle = std::atan2(normal.x() * d.y() - normal.y() * d.x(), normal.dot(d));
    if (std::abs(angle) <= limit) continue;
    const double a = std::copysign(limit, angle);
    direction[i] = Eigen::Vector2d(std::cos(a) * normal.x() - std::sin(a) * normal.y(),
                                   std::sin(a) * normal.x() + std::cos(a) * normal.y());
  }
  return direction;
}

// The O-block the elliptic equations are solved on: `rows` rows evenly spaced along
// lines from the wall nodes to the outer loop's nodes, the seam column repeated.
StructuredBlock algebraicOBlock(const std::vector<BladeNode>& wall, const OuterLoop& outer, int rows) {
  const int nT = static_cast<int>(wall.size());
  StructuredBlock o = makeBlock("OBlock", nT + 1, rows);
  const auto direction = lineDirections(wall, 20);
  for (int i = 0; i < nT; ++i) fillLine(o, i, wall[i].point, direction[i], outer.nodes[i]);
  for (int j = 0; j < rows; ++j) {
    o.xAt(nT, j) = o.xAt(0, j);
    o.yAt(nT, j) = o.yAt(0, j);
  }
  return o;
}

// An H-block of uniform cells between x = xBegin and x = xEnd whose edge at xEnd
// (interfaceAtEnd) or at xBegin carries the O-block's interface nodes `interface` (bottom
// to top).
StructuredBlock hBlock(const std::string& name, double xBegin, double xEnd, bool interfaceAtEnd,
                       const std::vector<Eigen::Vector2d>& interface, double pitch) {
  const int intervals = static_cast<int>(interface.size()) - 1;
  const double length = xEnd - xBegin;
  const int ni = 1 + std::max(1, static_cast<int>(std::lround(length / (pitch / intervals))));
  StructuredBlock h = makeBlock(name, ni, intervals + 1);
  const int iInterface = interfaceAtEnd ? ni - 1 : 0;
  for (int j = 0; j <= intervals; ++j)
    for (int i = 0; i < ni; ++i) {
      h.xAt(i, j) = i == iInterface ? interface[j].x() : xBegin + length * i / (ni - 1);
      h.yAt(i, j) = interface[j].y();
    }
  return h;
}

// The blade must lie strictly inside the O-block's outer loop: between the periodic
// boundaries and between the interfaces. Large yIn or yOut, or a small alphaCamber at a
// small pitch, make a periodic boundary cut through the blade; an interface at the leading
// or trailing edge (betaIn xIn or betaOut xOut near 0) cuts the rounded edge. Then no
// mesh exists, and saying so here is clearer (and cheaper) than the folded cells or the
// diverging smoother it would otherwise end in.
std::string outerLoopCrossing(const BladeShape& blade, const PassageBoundary& boundary,
                              const std::vector<BladeNode>& wall, bool& periodicCut) {
  periodicCut = false;
  auto metres = [](double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.6g m", v);
    return std::string(text);
  };
  // The periodic boundaries first: a draw they cut has no passage at all (the robustness
  // sweep's denominator counts the others).
  for (const auto& node : wall) {
    const double x = node.point.x(), y = node.point.y();
    if (x <= boundary.inletInterfaceX() || x >= boundary.outletInterfaceX()) continue;
    const bool below = y <= boundary.lowerY(x), above = y >= boundary.upperY(x);
    if (below || above) {
      periodicCut = true;
      // Where the blade is wider in y than the pitch no parameters can help: say so
      // rather than point at yIn, yOut and alphaCamber.
      const BladeYExtent widest = widestYExtent(blade);
      const std::string why =
          widest.extent >= boundary.pitch()
              ? "the blade's extent in y, " + metres(widest.extent) + " at x = " + metres(widest.x) +
                    ", is at least the pitch: it overlaps its periodic neighbour, and no meshing parameters give a passage"
              : "yIn, yOut or alphaCamber too far from the camber line for this pitch";
      return std::string("the ") + (below ? "lower" : "upper") + " periodic boundary cuts the blade at x = " +
             metres(x) + " (" + why + ")";
    }
  }
  // The interfaces against the profile itself (800 points), not the wall nodes: with few
  // nodes an interface could pass between two of them through the rounded edge.
  for (const Eigen::Vector2d& p : blade.sampleLoop(800)) {
    if (p.x() <= boundary.inletInterfaceX())
      return "the inlet interface (x = " + metres(boundary.inletInterfaceX()) +
             ") cuts the blade at y = " + metres(p.y()) + " (betaIn xIn too small)";
    if (p.x() >= boundary.outletInterfaceX())
      return "the outlet interface (x = " + metres(boundary.outletInterfaceX()) +
             ") cuts the blade at y = " + metres(p.y()) + " (betaOut xOut too small)";
  }
  return "";
}

// The O-block on the outer loop and the H-blocks beyond it, into `result` (its nN set):
// valid, or the problem.
void buildBlocks(HohMesh& result, const std::vector<BladeNode>& wall, const OuterLoop& outer,
                 const PassageBoundary& boundary, const PassageCondition& condition,
                 const HohMeshOptions& options) {
  const int nT = static_cast<int>(wall.size());
  // The O-block: solved on evenly spaced rows, then clustered to the wall along the
  // smoothed lines (LineRedistribution.hpp).
  const int nN = result.nN, J = nN - 1;
  StructuredBlock lines = algebraicOBlock(wall, outer, std::min(nN, options.smoothingRows));
  if (options.smooth && lines.nj >= 4) {
    const PeriodicOuterSegments periodic{outer.lowerPeriodicBegin(), outer.lowerPeriodicEnd(),
                                         outer.upperPeriodicBegin(), outer.upperPeriodicEnd(),
                                         Eigen::Vector2d(0, condition.pitch)};
    // The control values are found on a grid that keeps both edges (EllipticSmoother.hpp).
    const int leadingEdge = outer.lowerPeriodicEnd() + outer.inletLower;  // the wall's lower intervals
    result.smoothing = smoothOBlock(lines, options.elliptic, periodic, leadingEdge);
    if (!std::isfinite(result.smoothing.residual)) {
      result.problem = "O-block: the elliptic smoothing diverged";
      return;
    }
  }
  // A fold of the smoothed lines is named as such: placing rows along them cannot undo it.
  const std::string linesFold = findInvalidCell(lines);
  if (!linesFold.empty()) {
    result.problem = std::string(options.smooth ? "the smoothed" : "the algebraic") + " lines fold: " +
                     linesFold + " of " + std::to_string(lines.nj) + " rows";
    return;
  }
  StructuredBlock o = makeBlock("OBlock", nT + 1, nN);
  try {
    // The wall normals smoothed twice only: orthogonal to the wall to within a degree
    // except at the sharpest edges, where the raw normals of SIRT's trailing edge (radius
    // about 2 firstCellHeight) fold the second cell.
    const auto normals = lineDirections(wall, 2);
    // The first row alone within options.wallAngleLimit of the wall normal: turning the
    // whole blend back lowered Q_J a few rows up next to STD10's sharp trailing edge, and
    // with the parity of nT (docs/elliptic-smoothing.md).
    const auto firstRow = limitedToWallAngle(normals, wall, options.wallAngleLimit);
    // Where the smoothed lines leave the wall far from its normal (next to a sharp edge),
    // the turn from the normal into the line within the blend can cross the neighbouring
    // line's: then the rows are placed again with a blend twice as long, up to
    // options.wallBlendRetries times. A mesh valid at the first blend is never changed.
    double blend = options.wallBlendLength;
    for (int attempt = 0;; ++attempt, blend *= 2) {
      redistributeAlongLines(lines, o, condition.firstCellHeight, normals, blend, firstRow);
      result.wallBlendLength = blend;
      if (attempt == options.wallBlendRetries || findInvalidCell(o).empty()) break;
    }
  } catch (const std::invalid_argument& e) {
    result.problem = std::string("O-block: ") + e.what();
    return;
  }

  // H-blocks: uniform cells, their interface nodes the O-block's.
  auto outerNode = [&](int i) { return Eigen::Vector2d(o.xAt(i, J), o.yAt(i, J)); };
  const int inletIntervals = outer.inletLower + outer.inletUpper;
  const int inletBegin = outer.lowerPeriodicEnd();
  std::vector<Eigen::Vector2d> inletNodes, outletNodes;
  for (int j = 0; j <= inletIntervals; ++j) inletNodes.push_back(outerNode(inletBegin + j));
  // Outlet, bottom to top: the lower corner (O-block i = outletLower) down the O-block's
  // i to the seam, then from i = nT down to the upper corner.
  const int outletIntervals = outer.outletLower + outer.outletUpper;
  for (int j = 0; j <= outletIntervals; ++j)
    outletNodes.push_back(outerNode(j <= outer.outletLower ? outer.outletLower - j : nT - (j - outer.outletLower)));
  StructuredBlock hIn = hBlock("HInlet", boundary.inletX(), boundary.inletInterfaceX(), true,
                               inletNodes, condition.pitch);
  StructuredBlock hOut = hBlock("HOutlet", boundary.outletInterfaceX(), boundary.outletX(), false,
                                outletNodes, condition.pitch);
  const int niIn = hIn.ni, niOut = hOut.ni;
  StructuredMesh& mesh = result.mesh;
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
}

// The mesh with the parameters as given, with the later tries of HohMeshOptions;
// `periodicCut`: a periodic boundary cuts the blade (no passage: not smoothed, not moved).
HohMesh meshWithTries(const BladeShape& blade, const PassageCondition& condition,
                      const MeshingParameters& parameters, const HohMeshOptions& options,
                      bool& periodicCut) {
  const int nT = parameters.nT;
  HohMesh result;
  result.parameters = parameters;
  result.nN = std::max(2, static_cast<int>(std::lround(static_cast<double>(condition.nO) / nT)));
  const PassageBoundary boundary(blade, condition, parameters);

  const auto wall = distributeBladeNodes(blade, nT, parameters.gammaLe, parameters.gammaTe);
  result.problem = outerLoopCrossing(blade, boundary, wall, periodicCut);
  if (!result.problem.empty()) return result;
  int lowerIntervals = 0;
  while (wall[static_cast<std::size_t>(lowerIntervals)].side == BladeSide::lower) ++lowerIntervals;
  OuterLoop outer;
  try {
    outer = buildOuterLoop(boundary, nT, lowerIntervals, blade.leadingEdge().y(),
                           blade.trailingEdge().y(), parameters.splitIn, parameters.splitOut);
  } catch (const std::invalid_argument& e) {
    result.problem = e.what();
    return result;
  }

  buildBlocks(result, wall, outer, boundary, condition, options);
  // Where the lines fold (or the solve diverges), the mesh is built again asking less of
  // the smoothing, and the first valid try is kept (docs/elliptic-smoothing.md, "Second
  // try" and "Tries without the wall's orthogonality"): without the outer loop's
  // orthogonality control (the lines arrive at the angle the interior gives them, which a
  // tight passage or lines leaning far to reach their outer nodes need), then without the
  // wall's (the lines leave the wall as the algebraic grid has them, where the wall control
  // crosses the first rows next to a crowded edge), then without either.
  if (!result.valid && options.smooth) {
    struct Try {
      HohMeshOptions options;
      const char* without;  // HohMesh::retryWithout
    };
    std::vector<Try> tries;
    auto add = [&](bool dropOuter, bool dropWall, const char* without) {
      Try t{options, without};
      if (dropOuter) t.options.elliptic.outerOrthogonality = false;
      if (dropWall) t.options.elliptic.wallOrthogonality = false;
      tries.push_back(t);
    };
    const bool outerRetry = options.secondTryWithoutOuterOrthogonality && options.elliptic.outerOrthogonality;
    const bool wallRetry = options.triesWithoutWallOrthogonality && options.elliptic.wallOrthogonality;
    if (outerRetry) add(true, false, "the outer loop");
    if (wallRetry) add(false, true, "the wall");
    if (outerRetry && wallRetry) add(true, true, "the wall and the outer loop");
    for (const Try& t : tries) {
      HohMesh candidate;
      candidate.parameters = parameters;
      candidate.nN = result.nN;
      buildBlocks(candidate, wall, outer, boundary, condition, t.options);
      if (!candidate.valid) continue;
      candidate.firstTryProblem = result.problem;
      candidate.retryWithout = t.without;
      result = std::move(candidate);
      break;
    }
  }
  return result;
}

// `from` moved the fraction t of the way to `to` in the parameters that place the outer
// loop (yIn, yOut, alphaCamber, betaIn, betaOut); the others as in `from`.
MeshingParameters outerLoopMovedToward(const MeshingParameters& from, const MeshingParameters& to, double t) {
  MeshingParameters p = from;
  auto move = [t](double a, double b) { return a + t * (b - a); };
  p.yIn = move(from.yIn, to.yIn);
  p.yOut = move(from.yOut, to.yOut);
  p.alphaCamber = move(from.alphaCamber, to.alphaCamber);
  p.betaIn = move(from.betaIn, to.betaIn);
  p.betaOut = move(from.betaOut, to.betaOut);
  return p;
}

// "yIn 0.3 -> 0.21 m, gammaTE 0.5 -> 1.75": the parameters that differ, by the parameter
// table's names (lengths in metres).
std::string parameterMoves(const MeshingParameters& from, const MeshingParameters& to) {
  const auto& table = MeshingParameters::table();
  const auto a = from.toArray(), b = to.toArray();
  std::string text;
  for (int k = 0; k < MeshingParameters::size; ++k) {
    if (a[k] == b[k]) continue;
    char line[128];
    std::snprintf(line, sizeof line, "%s%s %.6g -> %.6g%s", text.empty() ? "" : ", ", table[k].name, a[k], b[k],
                  table[k].length ? " m" : "");
    text += line;
  }
  return text;
}

// The outer loop moved away from the blade so that it leaves `need` [m] of room
// (HohMeshOptions::outerLoopRoom): the smallest move toward the target's loop that does
// (bisection on the fraction of the way; all the way when even the target's loop leaves
// less, but more than as asked). Empty when the loop as asked leaves the room (the fold
// has another cause) or the target's loop leaves no more; `why` says how much room
// before and after.
std::optional<MeshingParameters> outerLoopWithRoom(const BladeShape& blade, const PassageCondition& condition,
                                                   const MeshingParameters& parameters, double need,
                                                   std::string& why) {
  const double chord = blade.parameters().chord;
  MeshingParameters target = MeshingParameters::defaults(chord);
  // The interfaces as far from the blade as the range box allows (betaIn, betaOut at
  // their upper bound): the defaults' would bring an interface nearer when asked further.
  const MeshingParameters upper = MeshingParameters::fromArray(MeshingParameters::upperBounds(chord));
  target.betaIn = upper.betaIn;
  target.betaOut = upper.betaOut;
  auto room = [&](double t) {
    return bladeClearance(blade, PassageBoundary(blade, condition, outerLoopMovedToward(parameters, target, t)));
  };
  const double before = room(0), atTarget = room(1);
  if (!(before < need) || !(atTarget > before)) return std::nullopt;
  double low = 0, high = 1, after = atTarget;  // after: the room at `high`
  if (atTarget >= need)
    for (int k = 0; k < 12; ++k) {
      const double t = 0.5 * (low + high), r = room(t);
      if (r >= need) {
        high = t;
        after = r;
      } else {
        low = t;
      }
    }
  char text[160];
  std::snprintf(text, sizeof text, "the blade came within %.3g chord of the outer loop; %.3g after the move",
                before / chord, after / chord);
  why = text;
  return outerLoopMovedToward(parameters, target, high);
}

}  // namespace

HohMesh buildHohMesh(const BladeShape& blade, const PassageCondition& condition,
                     const MeshingParameters& parameters, const HohMeshOptions& options) {
  if (parameters.nT < 8) throw std::invalid_argument("buildHohMesh: nT must be at least 8");
  bool periodicCut = false;
  HohMesh first = meshWithTries(blade, condition, parameters, options, periodicCut);
  if (first.valid || periodicCut) return first;
  // Meshes with moved parameters (HohMeshOptions::outerLoopRoom, clusteringMoves), each
  // move on top of the ones before; the first valid one is kept.
  MeshingParameters p = parameters;
  std::string reasons, failures;
  auto attempt = [&](const MeshingParameters& moved, const std::string& reason) {
    bool cut = false;
    HohMesh m = meshWithTries(blade, condition, moved, options, cut);
    const std::string why = reasons + (reasons.empty() || reason.empty() ? "" : "; ") + reason;
    if (m.valid) {
      m.parametersMoved = parameterMoves(parameters, moved) + " (" + why + ")";
      m.firstTryProblem = first.problem;
      return std::optional<HohMesh>(std::move(m));
    }
    failures += "; with " + parameterMoves(parameters, moved) + " still invalid: " + m.problem;
    return std::optional<HohMesh>();
  };
  if (options.outerLoopRoom > 0) {
    std::string why;
    if (const auto moved = outerLoopWithRoom(blade, condition, p, options.outerLoopRoom * blade.parameters().chord, why)) {
      if (auto m = attempt(*moved, why)) return std::move(*m);
      p = *moved;
      reasons = why;
    }
  }
  // A pair of parameters halfway to the defaults', then to them; `p` ends with them there.
  const MeshingParameters defaults = MeshingParameters::defaults(blade.parameters().chord);
  auto towardDefaults = [&](double MeshingParameters::*a, double MeshingParameters::*b,
                            const std::string& what) -> std::optional<HohMesh> {
    for (double t : {0.5, 1.0}) {
      MeshingParameters q = p;
      q.*a = p.*a + t * (defaults.*a - p.*a);
      q.*b = p.*b + t * (defaults.*b - p.*b);
      if (q.*a == p.*a && q.*b == p.*b) break;
      if (auto m = attempt(q, t < 1 ? what + " halfway to the defaults'" : "the defaults' " + what)) return m;
    }
    p.*a = defaults.*a;
    p.*b = defaults.*b;
    return std::nullopt;
  };
  if (options.clusteringMoves)
    if (auto m = towardDefaults(&MeshingParameters::gammaLe, &MeshingParameters::gammaTe, "node clustering"))
      return std::move(*m);
  if (options.splitMoves)
    if (auto m = towardDefaults(&MeshingParameters::splitIn, &MeshingParameters::splitOut, "interface splits"))
      return std::move(*m);
  first.problem += failures;
  return first;
}

}  // namespace passageMesh
