#include "passageMesh/polish/OBlockPolish.hpp"

#include <ceres/ceres.h>

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <vector>

#include "passageMesh/quality/MeshQuality.hpp"
#include "passageMesh/quality/OBlockNeighbours.hpp"

namespace passageMesh {

namespace {

// A node as a residual sees it: a parameter block (2 doubles) plus a translation (the
// periodic image of a node of the opposite segment).
struct NodeRef {
  double* xy = nullptr;
  double dx = 0, dy = 0;
};

// A residual over a few distinct parameter blocks; `entry` k reads block index[k] moved
// by (dx[k], dy[k]) (one block may serve two entries).
struct Entries {
  std::vector<int> index;
  std::vector<double> dx, dy;

  template <typename T>
  void at(const T* const* q, int k, T& x, T& y) const {
    const auto e = static_cast<std::size_t>(k);
    x = q[index[e]][0] + T(dx[e]);
    y = q[index[e]][1] + T(dy[e]);
  }
  template <typename T>
  Eigen::Matrix<T, 2, 1> point(const T* const* q, int k) const {
    Eigen::Matrix<T, 2, 1> p;
    at(q, k, p.x(), p.y());
    return p;
  }
};

// The corner at entry 0 between the edges to entries 1 and 2 (counter-clockwise):
// skewWeight cot |cot|^(power - 1). Fails (the step is rejected) where the corner is not
// convex.
struct CornerSkew : Entries {
  double weight = 1, power = 2;

  template <typename T>
  bool operator()(const T* const* q, T* r) const {
    const auto p = point(q, 0), e1 = (point(q, 1) - p).eval(), e2 = (point(q, 2) - p).eval();
    const T cross = e1.x() * e2.y() - e1.y() * e2.x();
    if (!(cross > T(0))) return false;
    const T cot = e1.dot(e2) / cross;
    r[0] = T(weight) * cot * pow(cot * cot + T(1e-12), T(0.5 * (power - 1)));
    return true;
  }
};

// J of a node from the points of its stencil, as the quality library computes it (both
// differences doubled): (b - a) x (d - c) from 4 points (central differences), or
// (b - a) x (3 e0 - 4 e1 + e2) from 5 (one-sided in eta).
template <typename T>
T stencilJacobian(const Eigen::Matrix<T, 2, 1>* p, int count) {
  const Eigen::Matrix<T, 2, 1> xi = p[1] - p[0];
  const Eigen::Matrix<T, 2, 1> eta = count == 4 ? (p[3] - p[2]).eval() : (T(3) * p[2] - T(4) * p[3] + p[4]).eval();
  return xi.x() * eta.y() - xi.y() * eta.x();
}

// jacobianWeight (ln J1 - ln J2 - target), J1 from the first `first` entries, J2 from the
// next `second` (stencilJacobian).
struct JacobianRatio : Entries {
  double weight = 1, target = 0;
  int first = 4, second = 4;

  template <typename T>
  T jacobian(const T* const* q, int start, int count) const {
    Eigen::Matrix<T, 2, 1> p[5];
    for (int k = 0; k < count; ++k) p[k] = point(q, start + k);
    return stencilJacobian(p, count);
  }

  template <typename T>
  bool operator()(const T* const* q, T* r) const {
    const T j1 = jacobian(q, 0, first), j2 = jacobian(q, first, second);
    if (!(j1 > T(0)) || !(j2 > T(0))) return false;
    r[0] = T(weight) * (log(j1) - log(j2) - T(target));
    return true;
  }
};

// smoothWeight ((a - 2 b + c) - (a0 - 2 b0 + c0)) / h: the change of a node's second
// difference along a row or a line, h the unpolished spacing there. The angles and the
// central-difference Jacobians do not see a zig-zag of alternate rows or lines (a kinked
// line can even square some corners); this term keeps the polished grid as smooth as the
// elliptic one while it bends.
struct SecondDifference : Entries {
  double weight = 1, x0 = 0, y0 = 0, spacing = 1;

  template <typename T>
  bool operator()(const T* const* q, T* r) const {
    const auto d2 = (point(q, 0) - T(2) * point(q, 1) + point(q, 2)).eval();
    r[0] = T(weight / spacing) * (d2.x() - T(x0));
    r[1] = T(weight / spacing) * (d2.y() - T(y0));
    return true;
  }
};

// The Jacobian of a stencil of node references as they stand.
double stencilJacobian(const std::vector<NodeRef>& s) {
  Eigen::Vector2d p[5];
  for (std::size_t k = 0; k < s.size(); ++k) p[k] = {s[k].xy[0] + s[k].dx, s[k].xy[1] + s[k].dy};
  return stencilJacobian(p, static_cast<int>(s.size()));
}

// The nodes that may move: within halfWidth of node (i, j) in both indices (i round the
// loop), or all when halfWidth is 0.
struct PolishWindow {
  int i = 0, j = 0, halfWidth = 0;
};

// The O-block's nodes as parameter blocks (the seam's repeated column left out), the
// ghost nodes of H-blocks as held blocks, and the residuals between them.
class PolishProblem {
 public:
  PolishProblem(const StructuredMesh& mesh, const OBlockNeighbours& neighbours, const OBlockPolishOptions& options,
                const PolishWindow& window = {})
      : o_(mesh.blocks[static_cast<std::size_t>(neighbours.oBlock)]), nb_(neighbours),
        options_(options), window_(window), n_(o_.ni - 1), top_(o_.nj - 1) {
    xy_.resize(static_cast<std::size_t>(2 * n_ * o_.nj));
    for (int j = 0; j <= top_; ++j)
      for (int i = 0; i < n_; ++i) {
        node(i, j)[0] = o_.xAt(i, j);
        node(i, j)[1] = o_.yAt(i, j);
      }
    // Ghosts in H-blocks are held copies (their own storage, so that a block is never both
    // held and moving).
    ghosts_.reserve(static_cast<std::size_t>(2 * n_));
    ghostOf_.assign(static_cast<std::size_t>(n_), nullptr);
    for (int i = 0; i < n_; ++i) {
      const OuterNeighbour& g = nb_.outer[static_cast<std::size_t>(i)];
      if (g.block < 0 || g.block == nb_.oBlock) continue;
      const StructuredBlock& h = mesh.blocks[static_cast<std::size_t>(g.block)];
      ghosts_.push_back(h.x[static_cast<std::size_t>(g.node)] + g.dx);
      ghosts_.push_back(h.y[static_cast<std::size_t>(g.node)] + g.dy);
      ghostOf_[static_cast<std::size_t>(i)] = &ghosts_[ghosts_.size() - 2];
    }
    markSharpEdges();
    build();
  }

  // Runs the Levenberg-Marquardt steps, calling `afterStep` with the nodes of each step in
  // the parameter blocks (and once before the first) until it returns false; returns the
  // number of steps.
  int solve(const std::function<bool()>& afterStep) {
    if (problem_.NumResidualBlocks() == 0) return 0;  // a window with no node free to move
    struct Callback : ceres::IterationCallback {
      const std::function<bool()>* f = nullptr;
      ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
        return (*f)() ? ceres::SOLVER_CONTINUE : ceres::SOLVER_TERMINATE_SUCCESSFULLY;
      }
    } callback;
    callback.f = &afterStep;
    ceres::Solver::Options solver;
    solver.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    solver.max_num_iterations = options_.iterations;
    solver.num_threads = 1;  // the same nodes whatever the machine
    solver.logging_type = ceres::SILENT;
    solver.update_state_every_iteration = true;
    solver.callbacks.push_back(&callback);
    ceres::Solver::Summary summary;
    ceres::Solve(solver, &problem_, &summary);
    return std::max(0, static_cast<int>(summary.iterations.size()) - 1);
  }

  void copyInto(StructuredBlock& o) const {
    for (int j = 0; j <= top_; ++j)
      for (int i = 0; i <= n_; ++i) {
        const double* p = &xy_[index(i, j)];
        o.xAt(i, j) = p[0];
        o.yAt(i, j) = p[1];
      }
  }

 private:
  // Node (i, j) of the O-block, i around the loop (wrapped: the seam column is column 0).
  int wrap(int i) const { return ((i % n_) + n_) % n_; }
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(2 * (wrap(i) + n_ * j)); }
  double* node(int i, int j) { return &xy_[index(i, j)]; }
  // Where the wall turns by more than sharpEdgeAngle at a node (a sharp edge's tip), that
  // node's Jacobian is a fraction of its neighbours' (about the sine of the half wedge
  // angle: its two neighbours lie on either side of the corner), and Q_J's minimum sits
  // there. Rows 2 .. heldWallRows of the columns within sharpEdgeColumns of it may move:
  // the tip's one-sided Jacobian reads row 2, while row 1 (first cell height, wall angle)
  // stays. Only in windows: freed in the whole-block pass they send it down another path,
  // lower on some meshes (docs/elliptic-smoothing.md "Sharp edges").
  void markSharpEdges() {
    nearSharpEdge_.assign(static_cast<std::size_t>(n_), false);
    if (window_.halfWidth == 0) return;
    const double cosLimit = std::cos(options_.sharpEdgeAngle * M_PI / 180);
    for (int i = 0; i < n_; ++i) {
      const Eigen::Vector2d a(node(i - 1, 0)[0], node(i - 1, 0)[1]), b(node(i, 0)[0], node(i, 0)[1]),
          c(node(i + 1, 0)[0], node(i + 1, 0)[1]);
      if ((b - a).normalized().dot((c - b).normalized()) >= cosLimit) continue;
      for (int d = -options_.sharpEdgeColumns; d <= options_.sharpEdgeColumns; ++d)
        nearSharpEdge_[static_cast<std::size_t>(wrap(i + d))] = true;
    }
  }

  bool held(const double* p) const {
    const std::less<const double*> before;  // pointers into different arrays: std::less orders them
    if (before(p, xy_.data()) || !before(p, xy_.data() + xy_.size())) return true;  // a ghost copy
    const auto k = static_cast<int>((p - xy_.data()) / 2);
    const int j = k / n_;
    if (j <= 1 || j == top_) return true;
    if (j <= options_.heldWallRows && !nearSharpEdge_[static_cast<std::size_t>(k % n_)]) return true;
    return window_.halfWidth > 0 && (ringDistance(k % n_, window_.i) > window_.halfWidth ||
                                     std::abs(j - window_.j) > window_.halfWidth);
  }
  int ringDistance(int a, int b) const {
    const int d = std::abs(wrap(a) - wrap(b));
    return std::min(d, n_ - d);
  }
  // A residual built at column i and row j reads nodes up to 2 columns and 2 rows away (a
  // node Jacobian's stencil beside the other's), except through a periodic image.
  static constexpr int residualReach = 2;
  // Whether residuals built at column i and row j can read a moving node: always for the
  // whole block, else within the window plus that margin. Those that read periodic images
  // (the outer row's Jacobians: nodes of the opposite segment, far away in i) are built
  // for every column; add() drops whatever moves nothing.
  bool mayReach(int i, int j, bool readsImages = false) const {
    if (window_.halfWidth == 0 || readsImages) return true;
    const int reach = window_.halfWidth + residualReach;
    return ringDistance(i, window_.i) <= reach && std::abs(j - window_.j) <= reach;
  }
  // The neighbour of outer node (i, top) beyond the outer row (Q's rule,
  // OBlockNeighbours.hpp): the periodic image of the partner line's node one row inside,
  // or the H-block's node (a held copy); none at a corner or a physical boundary.
  std::optional<NodeRef> beyondOuterRow(int i) {
    const auto column = static_cast<std::size_t>(wrap(i));
    const OuterNeighbour& g = nb_.outer[column];
    if (g.block < 0) return std::nullopt;
    if (g.block == nb_.oBlock) return NodeRef{node(g.node % o_.ni, g.node / o_.ni), g.dx, g.dy};
    return NodeRef{ghostOf_[column]};
  }
  // The stencil of node (i, j)'s Jacobian as the quality library takes it: 4 entries
  // (central differences), or 5 where it is one-sided in j (the wall row, and the outer
  // row where it has no neighbour beyond).
  std::vector<NodeRef> stencil(int i, int j) {
    if (j == 0)  // one-sided from the wall: xi reversed so that J comes out as 3 e0 - 4 e1 + e2 wants
      return {{node(i + 1, 0)}, {node(i - 1, 0)}, {node(i, 0)}, {node(i, 1)}, {node(i, 2)}};
    std::vector<NodeRef> s{{node(i - 1, j)}, {node(i + 1, j)}};
    if (j < top_) {
      s.push_back({node(i, j - 1)});
      s.push_back({node(i, j + 1)});
      return s;
    }
    if (const auto beyond = beyondOuterRow(i)) {  // central, across the outer row
      s.push_back({node(i, top_ - 1)});
      s.push_back(*beyond);
    } else {  // a corner or a physical boundary: one-sided
      s.push_back({node(i, top_)});
      s.push_back({node(i, top_ - 1)});
      s.push_back({node(i, top_ - 2)});
    }
    return s;
  }

  template <typename Functor>
  void add(Functor* f, const std::vector<std::vector<NodeRef>>& groups, int residuals = 1) {
    std::vector<double*> blocks;
    bool moves = false;
    for (const auto& group : groups)
      for (const NodeRef& r : group) {
        const auto it = std::find(blocks.begin(), blocks.end(), r.xy);
        f->index.push_back(static_cast<int>(it - blocks.begin()));
        if (it == blocks.end()) blocks.push_back(r.xy);
        f->dx.push_back(r.dx);
        f->dy.push_back(r.dy);
        moves = moves || !held(r.xy);
      }
    if (!moves) {  // a constant: nothing to optimise
      delete f;
      return;
    }
    auto* cost = new ceres::DynamicAutoDiffCostFunction<Functor, 10>(f);
    for (std::size_t k = 0; k < blocks.size(); ++k) cost->AddParameterBlock(2);
    cost->SetNumResiduals(residuals);
    problem_.AddResidualBlock(cost, nullptr, blocks);
  }

  void addJacobianRatio(int i1, int j1, int i2, int j2, bool keepRatio) {
    const auto s1 = stencil(i1, j1), s2 = stencil(i2, j2);
    auto* f = new JacobianRatio;
    f->weight = options_.jacobianWeight;
    f->first = static_cast<int>(s1.size());
    f->second = static_cast<int>(s2.size());
    const double j1v = stencilJacobian(s1), j2v = stencilJacobian(s2);
    f->target = keepRatio && j1v > 0 && j2v > 0 ? std::log(j1v) - std::log(j2v) : 0.0;
    add(f, {s1, s2});
  }

  void addSecondDifference(const NodeRef& a, const NodeRef& b, const NodeRef& c) {
    auto* f = new SecondDifference;
    f->weight = options_.smoothWeight;
    // Where the nodes stand now (a periodic image moved by its translation).
    const Eigen::Vector2d pa(a.xy[0] + a.dx, a.xy[1] + a.dy), pb(b.xy[0] + b.dx, b.xy[1] + b.dy),
        pc(c.xy[0] + c.dx, c.xy[1] + c.dy);
    const Eigen::Vector2d d2 = pa - 2 * pb + pc;
    f->x0 = d2.x();
    f->y0 = d2.y();
    f->spacing = 0.5 * ((pa - pb).norm() + (pc - pb).norm());
    add(f, {{a, b, c}}, 2);
  }

  void build() {
    // Corners, counter-clockwise in each cell (i clockwise round the blade, j outwards: a
    // right-handed system, as the mesher builds it).
    for (int j = 0; j < top_; ++j)
      for (int i = 0; i < n_; ++i) {
        if (!mayReach(i, j)) continue;
        const NodeRef a{node(i, j)}, b{node(i + 1, j)}, c{node(i + 1, j + 1)}, d{node(i, j + 1)};
        for (const auto& corner : {std::vector<NodeRef>{a, b, d}, std::vector<NodeRef>{b, c, a},
                                   std::vector<NodeRef>{c, d, b}, std::vector<NodeRef>{d, a, c}}) {
          auto* f = new CornerSkew;
          f->weight = options_.skewWeight;
          f->power = options_.skewPower;
          add(f, {corner});
        }
      }
    // Jacobians: along each row from the wall row to the outer row, across rows up to it
    // (those that reach the outer row for every column: periodic images). The wall row's
    // read rows 0-2, so they move only beside a sharp edge's tip.
    for (int j = 0; j <= top_; ++j)
      for (int i = 0; i < n_; ++i) {
        if (!mayReach(i, j, j >= top_ - 1)) continue;
        addJacobianRatio(i, j, i + 1, j, false);
        if (j < top_) addJacobianRatio(i, j, i, j + 1, true);
      }
    if (options_.smoothWeight > 0) {
      for (int j = 1; j < top_; ++j)
        for (int i = 0; i < n_; ++i) {
          if (!mayReach(i, j)) continue;
          addSecondDifference({node(i - 1, j)}, {node(i, j)}, {node(i + 1, j)});
          addSecondDifference({node(i, j - 1)}, {node(i, j)}, {node(i, j + 1)});
        }
      // Each line continued across the outer row into its neighbour beyond (the periodic
      // image of the partner's line, or the H-block's line): without it the polish bends
      // the lines where they cross the periodic cut and the interfaces, which Q does not
      // see and a flow solver does (T106A in simpleFoam: docs/elliptic-smoothing.md
      // "Polish").
      for (int i = 0; i < n_; ++i)
        if (const auto beyond = beyondOuterRow(i)) addSecondDifference({node(i, top_ - 1)}, {node(i, top_)}, *beyond);
    }
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j <= top_; ++j)
        if (held(node(i, j)) && problem_.HasParameterBlock(node(i, j))) problem_.SetParameterBlockConstant(node(i, j));
    for (std::size_t k = 0; k < ghosts_.size(); k += 2)
      if (problem_.HasParameterBlock(&ghosts_[k])) problem_.SetParameterBlockConstant(&ghosts_[k]);
  }

  const StructuredBlock& o_;
  const OBlockNeighbours& nb_;
  OBlockPolishOptions options_;
  PolishWindow window_;
  int n_, top_;
  std::vector<bool> nearSharpEdge_;  // per column: rows 2 .. heldWallRows move
  std::vector<double> xy_, ghosts_;
  std::vector<double*> ghostOf_;
  ceres::Problem problem_;
};

// Whether options.stop asks the polish to end; records it in the report.
bool stopAsked(const OBlockPolishOptions& options, OBlockPolishReport& report) {
  if (options.stop && options.stop->load()) report.interrupted = true;
  return report.interrupted;
}

// One Levenberg-Marquardt run over the window's nodes. The surrogate is not Q: of the
// steps' nodes, the ones with the highest Q are kept (the last step's are not always the
// best), and none unless Q rises above report.qualityAfter; returns whether it rose.
bool polishPass(StructuredMesh& mesh, const OBlockNeighbours& neighbours, const OBlockPolishOptions& options,
                const PolishWindow& window, std::chrono::steady_clock::time_point began,
                OBlockPolishReport& report) {
  StructuredBlock& o = mesh.blocks[static_cast<std::size_t>(neighbours.oBlock)];
  const double start = report.qualityAfter;
  StructuredBlock best;  // the O-block is only written once the best step is known
  StructuredMesh trial = mesh;
  StructuredBlock& trialO = trial.blocks[static_cast<std::size_t>(neighbours.oBlock)];
  MeshQualityWorkspace workspace;
  PolishProblem problem(mesh, neighbours, options, window);
  // Ceres calls back once before the first step (the nodes as given: Q known) and after each.
  int step = -1, bestStep = 0;
  report.iterations += problem.solve([&] {
    if (++step == 0) return !stopAsked(options, report);
    problem.copyInto(trialO);
    const double q = computeMeshQuality(trial, workspace).Q;
    report.stepQuality.push_back(q);
    if (q > report.qualityAfter) {
      report.qualityAfter = q;
      report.bestStep = static_cast<int>(report.stepQuality.size());
      bestStep = step;
      best = trialO;
    }
    if (options.afterStep) options.afterStep(report);
    if (stopAsked(options, report)) return false;
    // Q often falls for a few steps before it rises above the start: patience counts only
    // once it has (docs/elliptic-smoothing.md "Polish").
    return options.patience <= 0 || bestStep == 0 || step - bestStep < options.patience;
  });
  const bool raised = report.qualityAfter > start;
  if (raised) o = best;
  if (step <= 0 && report.interrupted) return false;  // stopped before its first step: no pass
  const bool whole = window.halfWidth <= 0;
  report.passLog.push_back({window.halfWidth, whole ? -1 : window.i, whole ? -1 : window.j, raised, report.qualityAfter,
                            std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count()});
  if (options.afterPass) options.afterPass(report);
  return raised;
}

}  // namespace

OBlockPolishReport polishOBlock(StructuredMesh& mesh, const OBlockPolishOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  OBlockNeighbours neighbours;
  findOBlockNeighbours(mesh, neighbours);
  const StructuredBlock& o = mesh.blocks[static_cast<std::size_t>(neighbours.oBlock)];
  if (!neighbours.wrapI) throw std::invalid_argument("polishOBlock: the O-block has no seam connection");
  if (o.nj < options.heldWallRows + 3 || options.heldWallRows < 1 || o.ni < 4)
    throw std::invalid_argument("polishOBlock: too few rows to polish (" + std::to_string(o.nj) + ")");

  OBlockPolishReport report;
  report.qualityBefore = report.qualityAfter = computeMeshQuality(mesh).Q;
  // A stop asked for between passes starts none.
  if (!stopAsked(options, report)) polishPass(mesh, neighbours, options, {}, start, report);
  // Then windows round the worst cell: Q is made of minima, and a window's few thousand
  // nodes factorise in milliseconds where the whole block takes seconds a step.
  for (int round = 0; round < options.windowRounds && !stopAsked(options, report); ++round) {
    const MeshQuality q = computeMeshQuality(mesh);
    // The worst Q_S cell's window, then where that raises no step's Q the worst Q_J cell's
    // (unless it is the same cell); each width in turn, widest first.
    const CellLocation worst[] = {q.worstQS, q.worstQJ};
    const int cells = q.worstQJ.i == q.worstQS.i && q.worstQJ.j == q.worstQS.j ? 1 : 2;
    bool raised = false;
    for (std::size_t w = 0; w < options.windowHalfWidths.size() && !raised; ++w) {
      const int halfWidth = options.windowHalfWidths[w];
      if (halfWidth <= 0) continue;  // 0 would be the whole block again
      for (int k = 0; k < cells && !raised && !stopAsked(options, report); ++k)
        raised = polishPass(mesh, neighbours, options, {worst[k].i, worst[k].j, halfWidth}, start, report);
    }
    if (!raised) break;
  }
  report.kept = report.qualityAfter > report.qualityBefore;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace passageMesh
