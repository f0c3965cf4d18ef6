#pragma once
/// \file spherical.h

#include "flexmb/joints/lower_pair.h"

namespace flexmb {

/// Spherical (ball) joint: the origins of markers i and j coincide.
class SphericalJoint final : public LowerPairJoint {
 public:
  explicit SphericalJoint(std::string name)
      : LowerPairJoint(std::move(name), {PairEquation::Coincide()}) {}
  const char* type() const override { return "spherical"; }
};

}  // namespace flexmb
