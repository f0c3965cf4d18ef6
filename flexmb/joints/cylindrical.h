#pragma once
/// \file cylindrical.h

#include "flexmb/joints/joint.h"

namespace flexmb {

/// Cylindrical joint: z axes of markers i and j aligned, origin j on the z axis of i; coordinates: translation along z_i [m], angle about z_i [rad].
class CylindricalJoint final : public Joint {
 public:
  explicit CylindricalJoint(std::string name) : Joint(std::move(name)) {}
  const char* type() const override { return "cylindrical"; }
  int NumEquations() const override { return 4; }
  std::string EquationName(int k) const override;
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const override;
  void AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                             Mat12& H) const override;
  int NumCoordinates() const override { return 2; }
  const char* CoordinateName(int k) const override { return k == 0 ? "translation" : "angle"; }
  bool CoordinateIsAngle(int k) const override { return k == 1; }
  double Coordinate(int k, const MarkerState& mi, const MarkerState& mj, Vec12* dq) const override;
};

}  // namespace flexmb
