#include "passageMesh/mesh/GridCoarsening.hpp"

namespace passageMesh {

Coarsening coarseningOf(const StructuredBlock& o, const MovingRows& rows, int coarsestLoop,
                        int coarsestMovingRows) {
  Coarsening c;
  const int n = o.ni - 1, first = rows.first(), last = rows.last(o);
  c.i = (n + 1) / 2 >= coarsestLoop;
  std::vector<int> coarse;
  for (int j = 0; j < first; ++j) coarse.push_back(j);
  for (int j = first + 1; j <= last; j += 2) coarse.push_back(j);
  for (int j = last + 1; j < o.nj; ++j) coarse.push_back(j);
  const int coarseMoving = static_cast<int>(coarse.size()) - first - rows.above;
  c.j = coarseMoving >= coarsestMovingRows;
  if (!c.j) {
    coarse.clear();
    for (int j = 0; j < o.nj; ++j) coarse.push_back(j);
  }
  c.fineRowOf = coarse;
  c.rowBelow.assign(static_cast<std::size_t>(o.nj), 0);
  c.rowWeightAbove.assign(static_cast<std::size_t>(o.nj), 0.0);
  for (std::size_t k = 0; k + 1 < coarse.size(); ++k)
    for (int j = coarse[k]; j < coarse[k + 1]; ++j) {
      c.rowBelow[static_cast<std::size_t>(j)] = static_cast<int>(k);
      c.rowWeightAbove[static_cast<std::size_t>(j)] =
          static_cast<double>(j - coarse[k]) / (coarse[k + 1] - coarse[k]);
    }
  c.rowBelow.back() = static_cast<int>(coarse.size()) - 1;
  return c;
}

StructuredBlock coarseBlock(const StructuredBlock& fine, const Coarsening& c) {
  const int nf = fine.ni - 1;
  StructuredBlock coarse;
  coarse.name = fine.name;
  coarse.ni = c.coarseLoop(nf) + 1;
  coarse.nj = static_cast<int>(c.fineRowOf.size());
  coarse.x.resize(static_cast<std::size_t>(coarse.ni) * coarse.nj);
  coarse.y.resize(coarse.x.size());
  const int nc = coarse.ni - 1;
  for (int J = 0; J < coarse.nj; ++J)
    for (int I = 0; I <= nc; ++I) {
      const int fi = I == nc ? nf : c.fineI(I), fj = c.fineRowOf[static_cast<std::size_t>(J)];
      coarse.xAt(I, J) = fine.xAt(fi, fj);
      coarse.yAt(I, J) = fine.yAt(fi, fj);
    }
  return coarse;
}

void interpolateDisplacement(const StructuredBlock& before, const StructuredBlock& after,
                             const Coarsening& c, const StructuredBlock& fine,
                             const MovingRows& rows, std::vector<double>& dx,
                             std::vector<double>& dy) {
  const int nf = fine.ni - 1, nc = after.ni - 1;
  dx.assign(fine.x.size(), 0.0);
  dy.assign(fine.x.size(), 0.0);
  for (int j = rows.first(); j <= rows.last(fine); ++j) {
    const int below = c.rowBelow[static_cast<std::size_t>(j)];
    const double up = c.rowWeightAbove[static_cast<std::size_t>(j)];
    for (int i = 0; i <= nf; ++i) {
      const int fi = i == nf ? 0 : i;
      const int left = c.i ? fi / 2 : fi, right = c.i ? (fi / 2 + 1) % nc : fi;
      const double r = c.i ? 0.5 * (fi % 2) : 0.0;
      double sx = 0, sy = 0;
      for (int a = 0; a < 2; ++a) {
        const double wj = a == 0 ? 1 - up : up;
        if (wj == 0) continue;
        for (int b = 0; b < 2; ++b) {
          const double wi = b == 0 ? 1 - r : r;
          if (wi == 0) continue;
          const int I = b == 0 ? left : right, J = below + a;
          sx += wj * wi * (after.xAt(I, J) - before.xAt(I, J));
          sy += wj * wi * (after.yAt(I, J) - before.yAt(I, J));
        }
      }
      dx[static_cast<std::size_t>(i + fine.ni * j)] = sx;
      dy[static_cast<std::size_t>(i + fine.ni * j)] = sy;
    }
  }
}

}  // namespace passageMesh
