#pragma once
/// \file fixed.h

#include "flexmb/joints/joint.h"

namespace flexmb {

/// Fixed joint: markers i and j coincide in position and orientation.
class FixedJoint final : public Joint {
 public:
  explicit FixedJoint(std::string name) : Joint(std::move(name)) {}
  const char* type() const override { return "fixed"; }
  int NumEquations() const override { return 6; }
  std::string EquationName(int k) const override;
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const override;
  void AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                             Mat12& H) const override;

};

}  // namespace flexmb
