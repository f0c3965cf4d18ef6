#pragma once
/// \file distance.h

#include "flexmb/joints/joint.h"

namespace flexmb {

/// Distance constraint (massless rod): the origins of markers i and j keep the distance length [m].
class DistanceJoint final : public Joint {
 public:
  explicit DistanceJoint(std::string name, double length) : Joint(std::move(name)), length_(length) {}
  const char* type() const override { return "distance"; }
  int NumEquations() const override { return 1; }
  std::string EquationName(int k) const override;
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const override;
  void AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                             Mat12& H) const override;
  /// Rod length [m].
  double length() const { return length_; }

 private:
  double length_;
};

}  // namespace flexmb
