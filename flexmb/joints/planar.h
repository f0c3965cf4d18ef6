#pragma once
/// \file planar.h

#include "flexmb/joints/joint.h"

namespace flexmb {

/// Planar joint: the x-y planes of markers i and j coincide (z axes parallel, origin j in the x-y plane of i).
class PlanarJoint final : public Joint {
 public:
  explicit PlanarJoint(std::string name) : Joint(std::move(name)) {}
  const char* type() const override { return "planar"; }
  int NumEquations() const override { return 3; }
  std::string EquationName(int k) const override;
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const override;
  void AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                             Mat12& H) const override;

};

}  // namespace flexmb
