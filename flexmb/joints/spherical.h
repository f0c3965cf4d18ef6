#pragma once
/// \file spherical.h

#include "flexmb/joints/joint.h"

namespace flexmb {

/// Spherical (ball) joint: the origins of markers i and j coincide.
class SphericalJoint final : public Joint {
 public:
  explicit SphericalJoint(std::string name) : Joint(std::move(name)) {}
  const char* type() const override { return "spherical"; }
  int NumEquations() const override { return 3; }
  std::string EquationName(int k) const override;
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const override;
  void AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                             Mat12& H) const override;

};

}  // namespace flexmb
