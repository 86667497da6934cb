// The initial guess of bladeFit, estimated from the points in the chord frame.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "passageMesh/blade/BladeFit.hpp"
#include "passageMesh/blade/BladeShape.hpp"

namespace passageMesh {

namespace {

// A side as (xi, eta) in the chord frame (chord-normalised), leading to trailing edge.
using Chain = std::vector<Eigen::Vector2d>;

// eta of the chain at xi: the crossing nearest the trailing edge (the leading edge may
// curl back behind xi = 0; the rest of a side is a graph over xi).
double etaAt(const Chain& chain, double xi) {
  for (std::size_t k = chain.size() - 1; k >= 1; --k) {
    const auto& a = chain[k - 1];
    const auto& b = chain[k];
    if ((a.x() - xi) * (b.x() - xi) <= 0 && a.x() != b.x())
      return a.y() + (b.y() - a.y()) * (xi - a.x()) / (b.x() - a.x());
  }
  return 0.0;
}

// The point of the loop furthest in direction -d (its support point): where the
// profile's normal is -d. The sides leave the camber line's ends perpendicular to it, so
// the camber end points are the support points along the camber directions there.
int supportPoint(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& d) {
  int best = 0;
  for (int k = 1; k < static_cast<int>(points.size()); ++k)
    if (points[k].dot(d) < points[best].dot(d)) best = k;
  return best;
}

Eigen::Vector2d direction(double degrees) {
  return {std::cos(degrees * M_PI / 180.0), std::sin(degrees * M_PI / 180.0)};
}

// Estimates every parameter in the chord frame of the leading-edge point `le` and the
// trailing-edge point `te` (indices into the counter-clockwise loop).
BladeParameters estimateInChordFrame(const std::vector<Eigen::Vector2d>& points, int le,
                                     int te) {
  const int n = static_cast<int>(points.size());
  const Eigen::Vector2d origin = points[le];
  const double chord = (points[te] - origin).norm();
  const Eigen::Vector2d ex = (points[te] - origin) / chord;
  const Eigen::Vector2d ey(-ex.y(), ex.x());
  auto toChordFrame = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2d((p - origin).dot(ex) / chord, (p - origin).dot(ey) / chord);
  };
  // Counter-clockwise: from the leading edge forward runs the lower side.
  Chain lower, upper;
  for (int k = le;; k = (k + 1) % n) {
    lower.push_back(toChordFrame(points[k]));
    if (k == te) break;
  }
  for (int k = le;; k = (k - 1 + n) % n) {
    upper.push_back(toChordFrame(points[k]));
    if (k == te) break;
  }

  // Camber line eta_c = xi (1 - xi) (b0 + b1 xi), least squares over the interior.
  constexpr int samples = 40;
  Eigen::MatrixXd a(samples, 2);
  Eigen::VectorXd rhs(samples);
  for (int k = 0; k < samples; ++k) {
    const double xi = 0.05 + 0.9 * k / (samples - 1);
    a(k, 0) = xi * (1 - xi);
    a(k, 1) = xi * xi * (1 - xi);
    rhs(k) = 0.5 * (etaAt(upper, xi) + etaAt(lower, xi));
  }
  const Eigen::Vector2d b = a.colPivHouseholderQr().solve(rhs);
  const double slopeLe = b(0), slopeTe = -(b(0) + b(1));
  auto camberEta = [&](double xi) { return xi * (1 - xi) * (b(0) + b(1) * xi); };

  BladeParameters p;
  const double degree = 180.0 / M_PI;
  p.xLe = origin.x();
  p.yLe = origin.y();
  p.chord = chord;
  p.stagger = std::atan2(ex.y(), ex.x()) * degree;
  p.thetaLe = p.stagger + std::atan(slopeLe) * degree;
  p.thetaTe = p.stagger + std::atan(slopeTe) * degree;
  p.distLe = std::clamp(std::hypot(1.0, slopeLe) / 3.0, 0.1, 1.0);
  p.distTe = std::clamp(std::hypot(1.0, slopeTe) / 3.0, 0.1, 1.0);
  // Thickness control values at the Greville abscissae of the thickness spline.
  const double greville[6] = {1.0 / 15, 0.2, 0.4, 0.6, 0.8, 14.0 / 15};
  for (int k = 0; k < 6; ++k) {
    const double xi = greville[k];
    p.thicknessUpper[k] = std::max(etaAt(upper, xi) - camberEta(xi), 1e-3);
    p.thicknessLower[k] = std::max(camberEta(xi) - etaAt(lower, xi), 1e-3);
  }
  // Edge radii from a circular edge: half-thickness t at distance x from it is ~sqrt(2 r x).
  auto edgeRadius = [&](double xi, double x) {
    const double t = 0.5 * (etaAt(upper, xi) - etaAt(lower, xi));
    return t * t / (2 * x);
  };
  p.radiusLe = std::clamp(edgeRadius(0.02, 0.02), 1e-3, 0.3);
  p.radiusTe = std::clamp(edgeRadius(0.98, 0.02), 1e-3, 0.1);
  return p;
}

// Distance along the ray origin + s d (s > 0) to the first crossing of the closed polygon,
// or a negative value when the ray misses it.
double rayToPolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& origin,
                    const Eigen::Vector2d& d) {
  double nearest = -1;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d a = polygon[k], e = polygon[(k + 1) % n] - a;
    const double denominator = d.x() * e.y() - d.y() * e.x();
    if (denominator == 0) continue;
    const Eigen::Vector2d w = a - origin;
    const double s = (w.x() * e.y() - w.y() * e.x()) / denominator;
    const double t = (w.x() * d.y() - w.y() * d.x()) / denominator;
    if (s > 0 && t >= 0 && t <= 1 && (nearest < 0 || s < nearest)) nearest = s;
  }
  return nearest;
}

// Thickness control values measured where they act: along the guessed camber line's
// normal at the thickness spline's Greville abscissae. With the camber line right, this
// puts the start close to the blade, which the chord-frame estimate does not on strongly
// cambered blades.
void thicknessAlongCamberNormals(const std::vector<Eigen::Vector2d>& points, BladeParameters& p) {
  const BladeShape camber(p);
  const double greville[6] = {1.0 / 15, 0.2, 0.4, 0.6, 0.8, 14.0 / 15};
  for (int k = 0; k < 6; ++k) {
    const Eigen::Vector2d c = camber.camberPoint(greville[k]);
    const Eigen::Vector2d t = camber.camberDerivative(greville[k]).normalized();
    const Eigen::Vector2d n(-t.y(), t.x());
    const double up = rayToPolygon(points, c, n), down = rayToPolygon(points, c, -n);
    if (up > 0 && down > 0) {
      p.thicknessUpper[k] = up / p.chord;
      p.thicknessLower[k] = down / p.chord;
    }
  }
}

}  // namespace

BladeParameters guessBladeParameters(const std::vector<Eigen::Vector2d>& points) {
  const int n = static_cast<int>(points.size());
  // First edges: the two points furthest apart; the leading edge is upstream (smaller x).
  // On a subsample of at most ~1000 points (the search is quadratic), then each end
  // refined among its neighbours in the full loop.
  const int stride = std::max(1, n / 1000);
  int le = 0, te = 1;
  double best = -1;
  for (int i = 0; i < n; i += stride)
    for (int j = i + stride; j < n; j += stride) {
      const double d = (points[i] - points[j]).squaredNorm();
      if (d > best) {
        best = d;
        le = i;
        te = j;
      }
    }
  for (int pass = 0; stride > 1 && pass < 3; ++pass)
    for (int* end : {&le, &te}) {
      const int other = end == &le ? te : le;
      const int centre = *end;
      for (int k = centre - 2 * stride; k <= centre + 2 * stride; ++k) {
        const int i = ((k % n) + n) % n;
        if ((points[i] - points[other]).squaredNorm() > (points[*end] - points[other]).squaredNorm())
          *end = i;
      }
    }
  if (points[le].x() > points[te].x()) std::swap(le, te);
  BladeParameters p = estimateInChordFrame(points, le, te);
  // Then move the edge points to where the profile is perpendicular to the estimated
  // camber directions, and estimate again.
  for (int iteration = 0; iteration < 3; ++iteration)
    p = guessBladeParameters(points, p.thetaLe, p.thetaTe);
  return p;
}

BladeParameters guessBladeParameters(const std::vector<Eigen::Vector2d>& points,
                                     double thetaLe, double thetaTe) {
  const int le = supportPoint(points, direction(thetaLe));
  const int te = supportPoint(points, -direction(thetaTe));
  if (le == te) return estimateInChordFrame(points, 0, static_cast<int>(points.size()) / 2);
  BladeParameters p = estimateInChordFrame(points, le, te);
  // Keep the requested edge angles: they are what this start explores.
  p.thetaLe = thetaLe;
  p.thetaTe = thetaTe;
  thicknessAlongCamberNormals(points, p);
  return p;
}

}  // namespace passageMesh
