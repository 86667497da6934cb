#include "passageMesh/passage/PassageBoundary.hpp"

namespace passageMesh {

PassageBoundary::PassageBoundary(const BladeShape& blade, const PassageCondition& condition,
                                 const MeshingParameters& parameters)
    : blade_(blade),
      condition_(condition),
      parameters_(parameters),
      le_(blade.leadingEdge()),
      te_(blade.trailingEdge()) {}

double PassageBoundary::lowerY(double x) const {
  const double halfPitch = 0.5 * condition_.pitch;
  const double yInlet = le_.y() + parameters_.yIn - halfPitch;
  const double yOutlet = te_.y() + parameters_.yOut - halfPitch;
  if (x < le_.x()) return yInlet;
  if (x >= te_.x()) return yOutlet;

  const double yCamber = blade_.camberY(x);
  const double sx = (te_.x() - x) / (te_.x() - le_.x());
  const double d = 0.05 * blade_.parameters().chord;
  const double D = le_.y() - te_.y();
  const double w = D * D / (D * D + d * d);
  const double s = D * (yCamber - te_.y()) / (D * D + d * d) + (1 - w) * sx;
  const double yC = yCamber + parameters_.yIn * s + parameters_.yOut * (1 - s) - halfPitch;
  const double yL = yInlet + (yOutlet - yInlet) * (1 - sx);
  const double a = parameters_.alphaCamber;
  return a * yC + (1 - a) * yL;
}

}  // namespace passageMesh
