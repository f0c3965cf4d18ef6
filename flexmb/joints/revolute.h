#pragma once
/// \file revolute.h

#include "flexmb/joints/lower_pair.h"

namespace flexmb {

/// Revolute joint: origins coincide, z axes of markers i and j aligned; coordinate: the angle of x_j about z_i [rad].
class RevoluteJoint final : public LowerPairJoint {
 public:
  explicit RevoluteJoint(std::string name)
      : LowerPairJoint(std::move(name), {PairEquation::Coincide(),
                                          PairEquation::Perpendicular(2, 0),
                                          PairEquation::Perpendicular(2, 1)}) {}
  const char* type() const override { return "revolute"; }
  int NumCoordinates() const override { return 1; }
  const char* CoordinateName(int) const override { return "angle"; }
  bool CoordinateIsAngle(int) const override { return true; }
  double Coordinate(int k, const MarkerState& mi, const MarkerState& mj, Vec12* dq) const override;
};

}  // namespace flexmb
