#pragma once
/// \file prismatic.h

#include "flexmb/joints/lower_pair.h"

namespace flexmb {

/// Prismatic joint: orientations of markers i and j equal, origin j on the z axis of i; coordinate: translation of j along z_i [m].
class PrismaticJoint final : public LowerPairJoint {
 public:
  explicit PrismaticJoint(std::string name)
      : LowerPairJoint(std::move(name), {PairEquation::Perpendicular(2, 0),
                                          PairEquation::Perpendicular(2, 1),
                                          PairEquation::Perpendicular(0, 1),
                                          PairEquation::InPlane(0),
                                          PairEquation::InPlane(1)}) {}
  const char* type() const override { return "prismatic"; }
  int NumCoordinates() const override { return 1; }
  const char* CoordinateName(int) const override { return "translation"; }
  double Coordinate(int k, const MarkerState& mi, const MarkerState& mj, Vec12* dq) const override;
};

}  // namespace flexmb
