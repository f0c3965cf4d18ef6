#pragma once
/// \file planar.h

#include "flexmb/joints/lower_pair.h"

namespace flexmb {

/// Planar joint: the x-y planes of markers i and j coincide (z axes parallel, origin j in the x-y plane of i).
class PlanarJoint final : public LowerPairJoint {
 public:
  explicit PlanarJoint(std::string name)
      : LowerPairJoint(std::move(name), {PairEquation::Perpendicular(2, 0),
                                          PairEquation::Perpendicular(2, 1),
                                          PairEquation::InPlane(2)}) {}
  const char* type() const override { return "planar"; }
};

}  // namespace flexmb
