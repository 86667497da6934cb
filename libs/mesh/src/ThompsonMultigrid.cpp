#include "passageMesh/mesh/ThompsonMultigrid.hpp"

#include "passageMesh/mesh/GridCoarsening.hpp"
#include "passageMesh/structured/CellValidity.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace passageMesh {

namespace {

struct Level {
  StructuredBlock* block = nullptr;  // the finest level's is the caller's
  StructuredBlock owned;
  GridControl control;
  MovingRows rows;
  Coarsening toCoarser;              // how the next level is made from this one
  std::vector<double> rx, ry;        // residual scratch
  StructuredBlock start;             // the nodes as restricted, before the coarse solve
  int n() const { return block->ni - 1; }
};

class Multigrid {
 public:
  Multigrid(StructuredBlock& finest, const GridControl& control, const MultigridOptions& options)
      : options_(options) {
    auto top = std::make_unique<Level>();
    top->block = &finest;
    top->control = control;
    top->rows = options.rows;
    levels_.push_back(std::move(top));
    while (true) {
      Level& fine = *levels_.back();
      const Coarsening c = coarseningOf(*fine.block, fine.rows, options_.coarsestLoop,
                                        options_.coarsestMovingRows);
      if (!c.i && !c.j) break;
      fine.toCoarser = c;
      auto coarse = std::make_unique<Level>();
      coarse->owned = coarseBlock(*fine.block, c);
      coarse->block = &coarse->owned;
      coarse->rows = fine.rows;
      restrictControls(fine, *coarse);
      levels_.push_back(std::move(coarse));
    }
  }

  int levels() const { return static_cast<int>(levels_.size()); }
  void cycle() { vCycle(0); }
  // New control functions for the finest grid, and from them the coarse grids'.
  void setControl(const GridControl& control) {
    levels_[0]->control.phi = control.phi;
    levels_[0]->control.psi = control.psi;
    for (std::size_t l = 0; l + 1 < levels_.size(); ++l) restrictControls(*levels_[l], *levels_[l + 1]);
  }

 private:
  void sweeps(Level& level, int count) {
    for (int k = 0; k < count; ++k)
      sweepThompson(*level.block, level.control, level.rows, options_.relaxation);
  }

  void vCycle(std::size_t l) {
    Level& fine = *levels_[l];
    if (l + 1 == levels_.size()) {
      sweeps(fine, options_.coarsestSweeps);
      return;
    }
    sweeps(fine, options_.preSweeps);
    Level& coarse = *levels_[l + 1];
    restrictToCoarse(fine, coarse);
    vCycle(l + 1);
    correctFromCoarse(coarse, fine);
    sweeps(fine, options_.postSweeps);
  }

  // phi, psi are per index step: doubled by coarsening. Held below 2 in size, where the
  // line systems would lose diagonal dominance (the coarse grid then only approximates the
  // fine one there, which costs convergence speed, not accuracy).
  void restrictControls(const Level& fine, Level& coarse) {
    const Coarsening& c = fine.toCoarser;
    const int nf = fine.n(), nc = coarse.n(), nj = coarse.block->nj;
    constexpr double limit = 1.8;
    const std::size_t nodes = static_cast<std::size_t>(nc) * nj;
    auto restrictOne = [&](const std::vector<double>& from, double factor) {
      std::vector<double> to;
      if (from.empty()) return to;
      to.resize(nodes);
      for (int J = 0; J < nj; ++J)
        for (int I = 0; I < nc; ++I)
          to[static_cast<std::size_t>(I + nc * J)] = std::clamp(
              from[static_cast<std::size_t>(c.fineI(I) + nf * c.fineRowOf[static_cast<std::size_t>(J)])] * factor,
              -limit, limit);
      return to;
    };
    coarse.control.phi = restrictOne(fine.control.phi, c.i ? 2.0 : 1.0);
    coarse.control.psi = restrictOne(fine.control.psi, c.j ? 2.0 : 1.0);
  }

  // Coarse nodes by injection; coarse force = N_H(restricted nodes) + scale * (the fine
  // defect, full-weighted over the moving rows): the FAS right-hand side.
  void restrictToCoarse(Level& fine, Level& coarse) {
    const Coarsening& c = fine.toCoarser;
    const StructuredBlock& f = *fine.block;
    StructuredBlock& g = *coarse.block;
    const int nf = fine.n(), nc = coarse.n();
    g = coarseBlock(f, c);
    coarse.start = g;
    thompsonResidualField(f, fine.control, fine.rows, fine.rx, fine.ry);
    GridControl& gc = coarse.control;
    gc.forceX.clear();
    gc.forceY.clear();
    thompsonResidualField(g, gc, coarse.rows, coarse.rx, coarse.ry);  // N_H of the start
    gc.forceX.assign(static_cast<std::size_t>(nc) * g.nj, 0.0);
    gc.forceY.assign(gc.forceX.size(), 0.0);
    const double scale = c.residualScale();
    const int firstMoving = fine.rows.first(), lastMoving = fine.rows.last(f);
    for (int J = coarse.rows.first(); J <= coarse.rows.last(g); ++J) {
      const int fj = c.fineRowOf[static_cast<std::size_t>(J)];
      for (int I = 0; I < nc; ++I) {
        const int fi = c.fineI(I);
        double dx = 0, dy = 0, weights = 0;
        for (int sj = c.j ? -1 : 0; sj <= (c.j ? 1 : 0); ++sj) {
          if (fj + sj < firstMoving || fj + sj > lastMoving) continue;
          for (int si = c.i ? -1 : 0; si <= (c.i ? 1 : 0); ++si) {
            const double w = (sj == 0 ? 1.0 : 0.5) * (si == 0 ? 1.0 : 0.5);
            const std::size_t kf = static_cast<std::size_t>((fi + si + nf) % nf + nf * (fj + sj));
            dx += w * fine.rx[kf];
            dy += w * fine.ry[kf];
            weights += w;
          }
        }
        const std::size_t k = static_cast<std::size_t>(I + nc * J);
        gc.forceX[k] = coarse.rx[k] - scale * dx / weights;  // the defect is -residual
        gc.forceY[k] = coarse.ry[k] - scale * dy / weights;
      }
    }
  }

  // Adds the coarse correction, interpolated bilinearly in index space, to the fine grid's
  // moving rows; halves it while it would fold a cell (four times, then drops it).
  void correctFromCoarse(const Level& coarse, Level& fine) {
    const Coarsening& c = fine.toCoarser;
    StructuredBlock& f = *fine.block;
    const int nf = fine.n();
    interpolateDisplacement(coarse.start, *coarse.block, c, f, fine.rows, correctionX_, correctionY_);
    const std::vector<double> x0 = f.x, y0 = f.y;
    const bool validBefore = cellsValidFrom(f, fine.rows.first() - 1);
    double factor = 1;
    for (int attempt = 0; attempt < 5; ++attempt, factor *= 0.5) {
      for (std::size_t k = 0; k < f.x.size(); ++k) {
        f.x[k] = x0[k] + factor * correctionX_[k];
        f.y[k] = y0[k] + factor * correctionY_[k];
      }
      for (int j = 0; j < f.nj; ++j) {
        f.xAt(nf, j) = f.xAt(0, j);
        f.yAt(nf, j) = f.yAt(0, j);
      }
      if (!validBefore || cellsValidFrom(f, fine.rows.first() - 1)) return;
    }
    f.x = x0;
    f.y = y0;
  }

  MultigridOptions options_;
  std::vector<std::unique_ptr<Level>> levels_;
  std::vector<double> correctionX_, correctionY_;
};

}  // namespace

MultigridReport solveThompsonMultigrid(StructuredBlock& o, GridControl& control,
                                       const MultigridOptions& options,
                                       const ControlUpdate& update) {
  Multigrid multigrid(o, control, options);
  MultigridReport report;
  report.levels = multigrid.levels();
  const ThompsonReport r = iterateUntilConverged(
      options.maxCycles, options.tolerance,
      [&] {
        if (update) {
          update(o, control);
          multigrid.setControl(control);
        }
        multigrid.cycle();
      },
      [&] { return thompsonResidual(o, control, options.rows); }, options.stallCycles);
  report.cycles = r.sweeps;
  report.residual = r.residual;
  report.converged = r.converged;
  return report;
}

}  // namespace passageMesh
