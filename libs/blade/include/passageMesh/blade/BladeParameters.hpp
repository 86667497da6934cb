#pragma once
// The blade shape parameters (BSP) of the camber/thickness parametrization
// (docs/blade-parametrization.md, after Agromayor et al. 2021, ParaBlade).
//
// Conventions: lengths in metres, angles in degrees measured from +x (the axial direction,
// flow towards +x), counter-clockwise positive. The chord C is the distance from the
// camber line's leading-edge point to its trailing-edge point; distLe, distTe, radiusLe,
// radiusTe and the twelve thickness values are fractions of C, so a blade scaled by s keeps
// all of them and only chord (and position) change.
#include <array>
#include <string>

namespace passageMesh {

struct BladeParameters {
  static constexpr int size = 22;
  static constexpr int radiusLeIndex = 8, radiusTeIndex = 9;  // in toArray() order

  double xLe = 0;        // camber line leading-edge point [m]
  double yLe = 0;
  double chord = 1;      // |trailing-edge point - leading-edge point| [m]
  double stagger = 0;    // direction of the chord line [deg]
  double thetaLe = 0;    // camber line direction at the leading edge [deg]
  double thetaTe = 0;    // camber line direction at the trailing edge [deg]
  double distLe = 0.3;   // camber Bezier: |P1 - P0| / C
  double distTe = 0.3;   // camber Bezier: |P3 - P2| / C
  double radiusLe = 0.02;  // leading-edge radius of curvature / C
  double radiusTe = 0.01;  // trailing-edge radius of curvature / C
  std::array<double, 6> thicknessUpper{};  // upper (+normal) side half-thickness / C
  std::array<double, 6> thicknessLower{};  // lower (-normal) side half-thickness / C

  std::array<double, size> toArray() const;
  static BladeParameters fromArray(const std::array<double, size>& values);
  static BladeParameters fromArray(const double* values);
  // The names used in bladeParameters.xml and etc/bladeParameterRange.xml, in array order.
  static const std::array<std::string, size>& names();
};

}  // namespace passageMesh
