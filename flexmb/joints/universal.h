#pragma once
/// \file universal.h

#include "flexmb/joints/joint.h"

namespace flexmb {

/// Universal (Cardan) joint: origins coincide; the z axes of markers i and j are the cross axes and stay perpendicular.
class UniversalJoint final : public Joint {
 public:
  explicit UniversalJoint(std::string name) : Joint(std::move(name)) {}
  const char* type() const override { return "universal"; }
  int NumEquations() const override { return 4; }
  std::string EquationName(int k) const override;
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const override;
  void AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                             Mat12& H) const override;

};

}  // namespace flexmb
