#pragma once
/// \file revolute.h

#include "flexmb/joints/joint.h"

namespace flexmb {

/// Revolute joint: origins coincide, z axes of markers i and j aligned; coordinate: the angle of x_j about z_i [rad].
class RevoluteJoint final : public Joint {
 public:
  explicit RevoluteJoint(std::string name) : Joint(std::move(name)) {}
  const char* type() const override { return "revolute"; }
  int NumEquations() const override { return 5; }
  std::string EquationName(int k) const override;
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const override;
  void AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                             Mat12& H) const override;
  int NumCoordinates() const override { return 1; }
  const char* CoordinateName(int) const override { return "angle"; }
  bool CoordinateIsAngle(int) const override { return true; }
  double Coordinate(int k, const MarkerState& mi, const MarkerState& mj, Vec12* dq) const override;
};

}  // namespace flexmb
