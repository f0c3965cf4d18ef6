#pragma once
/// \file cylindrical.h

#include "flexmb/joints/lower_pair.h"

namespace flexmb {

/// Cylindrical joint: z axes of markers i and j aligned, origin j on the z axis of i; coordinates: translation along z_i [m], angle about z_i [rad].
class CylindricalJoint final : public LowerPairJoint {
 public:
  explicit CylindricalJoint(std::string name)
      : LowerPairJoint(std::move(name), {PairEquation::Perpendicular(2, 0),
                                          PairEquation::Perpendicular(2, 1),
                                          PairEquation::InPlane(0),
                                          PairEquation::InPlane(1)}) {}
  const char* type() const override { return "cylindrical"; }
  int NumCoordinates() const override { return 2; }
  const char* CoordinateName(int k) const override { return k == 0 ? "translation" : "angle"; }
  bool CoordinateIsAngle(int k) const override { return k == 1; }
  double Coordinate(int k, const MarkerState& mi, const MarkerState& mj, Vec12* dq) const override;
};

}  // namespace flexmb
