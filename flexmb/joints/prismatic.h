#pragma once
/// \file prismatic.h

#include "flexmb/joints/joint.h"

namespace flexmb {

/// Prismatic joint: orientations of markers i and j equal, origin j on the z axis of i; coordinate: translation of j along z_i [m].
class PrismaticJoint final : public Joint {
 public:
  explicit PrismaticJoint(std::string name) : Joint(std::move(name)) {}
  const char* type() const override { return "prismatic"; }
  int NumEquations() const override { return 5; }
  std::string EquationName(int k) const override;
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const override;
  void AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                             Mat12& H) const override;
  int NumCoordinates() const override { return 1; }
  const char* CoordinateName(int) const override { return "translation"; }
  double Coordinate(int k, const MarkerState& mi, const MarkerState& mj, Vec12* dq) const override;
};

}  // namespace flexmb
