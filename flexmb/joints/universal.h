#pragma once
/// \file universal.h

#include "flexmb/joints/lower_pair.h"

namespace flexmb {

/// Universal (Cardan) joint: origins coincide; the z axes of markers i and j are the cross axes and stay perpendicular.
class UniversalJoint final : public LowerPairJoint {
 public:
  explicit UniversalJoint(std::string name)
      : LowerPairJoint(std::move(name), {PairEquation::Coincide(),
                                          PairEquation::Perpendicular(2, 2)}) {}
  const char* type() const override { return "universal"; }
};

}  // namespace flexmb
