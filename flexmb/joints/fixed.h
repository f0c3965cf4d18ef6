#pragma once
/// \file fixed.h

#include "flexmb/joints/lower_pair.h"

namespace flexmb {

/// Fixed joint: markers i and j coincide in position and orientation.
class FixedJoint final : public LowerPairJoint {
 public:
  explicit FixedJoint(std::string name)
      : LowerPairJoint(std::move(name), {PairEquation::Coincide(),
                                          PairEquation::Perpendicular(2, 0),
                                          PairEquation::Perpendicular(2, 1),
                                          PairEquation::Perpendicular(0, 1)}) {}
  const char* type() const override { return "fixed"; }
};

}  // namespace flexmb
