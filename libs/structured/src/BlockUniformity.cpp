#include "passageMesh/structured/BlockUniformity.hpp"

#include <algorithm>
#include <cmath>

namespace passageMesh {

double blockNonUniformity(const StructuredBlock& b) {
  auto edge = [&](int i0, int j0, int i1, int j1) {
    return std::hypot(b.xAt(i1, j1) - b.xAt(i0, j0), b.yAt(i1, j1) - b.yAt(i0, j0));
  };
  double worst = 0;
  for (int direction = 0; direction < 2; ++direction) {
    const int di = direction == 0 ? 1 : 0, dj = 1 - di;
    double sum = 0;
    int count = 0;
    for (int j = 0; j + dj < b.nj; ++j)
      for (int i = 0; i + di < b.ni; ++i, ++count) sum += edge(i, j, i + di, j + dj);
    const double mean = sum / count;
    for (int j = 0; j + dj < b.nj; ++j)
      for (int i = 0; i + di < b.ni; ++i)
        worst = std::max(worst, std::abs(edge(i, j, i + di, j + dj) / mean - 1));
  }
  return worst;
}

}  // namespace passageMesh
