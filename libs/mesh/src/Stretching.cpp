#include "passageMesh/mesh/Stretching.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace passageMesh {

namespace {
// Below this strength the tanh ratios are replaced by their limit, the identity, whose
// error there is O(gamma^2) ~ 1e-16.
constexpr double uniformBelow = 1e-8;
}  // namespace

double tanhClusterStart(double xi, double gamma) {
  if (gamma < uniformBelow) return xi;
  // = 1 - tanh(gamma (1 - xi)) / tanh(gamma), written without the cancellation that loses
  // digits near the wall (where the value is ~1e-5 and the ratio ~1 - 1e-5).
  return std::sinh(gamma * xi) / (std::cosh(gamma * (1.0 - xi)) * std::sinh(gamma));
}

double tanhClusterEnd(double xi, double gamma) {
  if (gamma < uniformBelow) return xi;
  return std::tanh(gamma * xi) / std::tanh(gamma);
}

double tanhStretch(double xi, double gammaStart, double gammaEnd) {
  const double w = xi * xi * (3.0 - 2.0 * xi);
  return (1.0 - w) * tanhClusterStart(xi, gammaStart) + w * tanhClusterEnd(xi, gammaEnd);
}

double wallClusteringStrength(int n, double length, double firstSpacing) {
  if (n < 2 || !(length > 0) || !(firstSpacing > 0))
    throw std::invalid_argument("wall clustering: need n >= 2 and positive lengths");
  const double h = 1.0 / (n - 1);
  const double target = firstSpacing / length;
  if (!(target < h))
    throw std::invalid_argument("wall clustering: first spacing " + std::to_string(firstSpacing) +
                                " is not below the uniform spacing " + std::to_string(length * h));
  // s_1 / length = tanhClusterStart(h, gamma) falls monotonically from h (gamma = 0) to 0.
  // Newton on its logarithm, kept inside a bisection bracket: about six steps where
  // bisection alone took some fifty, each with three hyperbolic functions, once per line.
  double lo = 0, hi = 1;
  while (tanhClusterStart(h, hi) > target) {
    lo = hi;
    hi *= 2;
    if (hi > 1e4) throw std::invalid_argument("wall clustering: first spacing too small");
  }
  const double logTarget = std::log(target);
  double gamma = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * hi; ++iteration) {
    const double f = tanhClusterStart(h, gamma);
    (f > target ? lo : hi) = gamma;
    // d ln f / d gamma = h coth(gamma h) - (1 - h) tanh(gamma (1 - h)) - coth(gamma) < 0
    const double slope = h / std::tanh(gamma * h) - (1 - h) * std::tanh(gamma * (1 - h)) - 1 / std::tanh(gamma);
    double next = gamma - (std::log(f) - logTarget) / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - gamma) <= 1e-15 * gamma) return next;
    gamma = next;
  }
  return gamma;
}

std::vector<double> wallClusteredDistances(int n, double length, double firstSpacing) {
  const double gamma = wallClusteringStrength(n, length, firstSpacing);
  std::vector<double> s(n);
  for (int j = 0; j < n; ++j) s[j] = length * tanhClusterStart(static_cast<double>(j) / (n - 1), gamma);
  s[0] = 0.0;
  s[n - 1] = length;
  return s;
}

void moveLastSpacing(std::vector<double>& s, double lastSpacing) {
  const int last = static_cast<int>(s.size()) - 1;
  if (last < 2 || !(lastSpacing > 0)) return;
  // s_j grows by c f(t_j), f(t) = t^8 (t - 1), t_j = j / last: f vanishes at both ends, so
  // the ends stay, and the last spacing grows by c (f(1) - f(1 - h)) = c h (1 - h)^8,
  // h = 1 / last.
  auto f = [last](int j) {
    const double t = static_cast<double>(j) / last, t2 = t * t, t4 = t2 * t2;
    return t4 * t4 * (t - 1);
  };
  // f(1) - f(1 - h) = h (1 - h)^8 = -f(last - 1)
  const double wanted = (lastSpacing - (s[last] - s[last - 1])) / -f(last - 1);
  // The largest |c| of that sign for which no spacing falls below half of what it was:
  // s_j - s_{j-1} + c (f_j - f_{j-1}) >= (s_j - s_{j-1}) / 2. Clipping c there keeps the
  // nodes continuous in lastSpacing and in the line length, and so Q continuous in the
  // meshing parameters (halving c until the spacings passed made whole lines jump).
  double limit = std::abs(wanted);
  for (int j = 1; j <= last; ++j) {
    const double change = wanted >= 0 ? f(j) - f(j - 1) : f(j - 1) - f(j);  // per unit |c|
    if (change < 0) limit = std::min(limit, std::max(0.0, 0.5 * (s[j] - s[j - 1]) / -change));
  }
  const double c = std::copysign(limit, wanted);
  for (int j = 1; j < last; ++j) s[j] += c * f(j);
}

}  // namespace passageMesh
