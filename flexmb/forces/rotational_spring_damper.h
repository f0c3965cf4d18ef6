#pragma once
/// \file rotational_spring_damper.h
/// Torsional spring-damper about the z axis of marker i.

#include <memory>

#include "flexmb/forces/force_element.h"
#include "flexmb/math/scalar_function.h"

namespace flexmb {

/// Torque laws of a RotationalSpringDamper. The spring torque is
/// stiffness * delta, or torque_angle(delta) when that function is given,
/// with the deflection delta = theta - angle0 [rad]; the damper torque is
/// damping * thetadot [N m].
struct RotationalSpringDamperLaw {
  double angle0 = 0.0;     ///< angle at which the spring torque is `preload` [rad]
  double stiffness = 0.0;  ///< linear torsional stiffness [N m/rad] (without torque_angle)
  double damping = 0.0;    ///< torsional damping [N m s/rad]
  double preload = 0.0;    ///< spring torque at angle0 [N m]
  std::shared_ptr<const ScalarFunction> torque_angle;  ///< tau(delta) [N m], delta [rad]; optional
};

/// Torsional spring-damper between markers i and j, for use with a joint
/// that keeps z_i parallel to z_j (revolute, cylindrical). theta is the angle
/// of x_j about z_i, atan2(y_i . x_j, x_i . x_j) (primitives::RelativeAngle);
/// delta = theta - angle0 is wrapped to (-pi, pi], so the spring has one
/// equilibrium per revolution. The rate is thetadot = z_i . (w_j - w_i),
/// which is the derivative of theta while z_i is parallel to z_j. The torque
///   T = -(spring(delta) + preload + damping * thetadot)
/// acts about z_i: m_j = T z_i on marker j and m_i = -T z_i on marker i; no
/// forces. A positive stiffness therefore turns j back towards angle0.
/// Throws NumericalError if x_j is parallel to z_i (angle undefined).
class RotationalSpringDamper final : public ForceElement {
 public:
  /// Throws InputError naming the element for a negative or non-finite
  /// stiffness or damping, or non-finite angle0 or preload.
  RotationalSpringDamper(std::string name, RotationalSpringDamperLaw law);
  const char* type() const override { return "rotational_spring_damper"; }
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const override;
  /// 0.5 k delta^2 + preload delta; for torque_angle the integral of
  /// tau(s) from 0 to delta (Simpson's rule, 64 intervals) plus preload delta.
  /// [J]
  double PotentialEnergy(const MarkerState& mi, const MarkerState& mj, double t) const override;
  /// The torque laws.
  const RotationalSpringDamperLaw& law() const { return law_; }

 private:
  RotationalSpringDamperLaw law_;
};

}  // namespace flexmb
