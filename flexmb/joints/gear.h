#pragma once
/// \file gear.h
/// Gear (coupler) between two shafts on revolute joints of a common carrier:
/// one constraint tying the shafts' rotation angles by a ratio.

#include "flexmb/joints/joint.h"

namespace flexmb {

/// Gear between marker i on shaft 1 (axis z_i) and marker j on shaft 2
/// (axis z_j), the shafts turning in revolute joints of a common carrier
/// (so z_i and z_j keep their directions relative to each other; they must
/// not be parallel). Convention: at the reference configuration (zero
/// angles) x_i points along z_j and x_j along z_i. The shaft angles are
///   theta_i = -atan2(z_j . y_i, z_j . x_i),  theta_j = -atan2(z_i . y_j, z_i . x_j)
/// (the rotation of each shaft about its own axis relative to the other
/// shaft's axis, i.e. relative to the carrier, whatever the carrier's
/// motion) and the constraint is
///   phi = wrap(theta_i - ratio theta_j) = 0
/// with wrap to (-pi, pi], so shaft i may turn any number of revolutions
/// (e.g. a steering column driving a pitman arm through a steering gear of
/// ratio 20). D is analytic; the geometric stiffness is a central
/// difference of D (12 evaluations).
class GearJoint final : public Joint {
 public:
  /// `ratio` [-]: theta_i / theta_j, non-zero and finite; throws InputError
  /// naming the joint otherwise.
  GearJoint(std::string name, double ratio);
  const char* type() const override { return "gear"; }
  int NumEquations() const override { return 1; }
  std::string EquationName(int k) const override;
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const override;
  void AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                             Mat12& H) const override;
  /// Shaft angles theta_i, theta_j [rad] in (-pi, pi] (see the class comment).
  static Eigen::Vector2d ShaftAngles(const MarkerState& mi, const MarkerState& mj);
  /// Gear ratio theta_i / theta_j [-].
  double ratio() const { return ratio_; }

 private:
  // phi and its derivative with respect to the marker variations
  double Phi(const MarkerState& mi, const MarkerState& mj, Vec12* d) const;
  double ratio_;
};

}  // namespace flexmb
