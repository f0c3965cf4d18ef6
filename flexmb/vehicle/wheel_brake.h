#pragma once
/// \file wheel_brake.h
/// Friction brake of one wheel: a torque opposing the wheel's spin relative
/// to its carrier, smoothed through zero spin.

#include <memory>
#include <string>

#include "flexmb/forces/force_element.h"
#include "flexmb/math/scalar_function.h"

namespace flexmb::vehicle {

/// Brake on the wheel bearing: marker i on the carrier (knuckle or axle),
/// marker j on the wheel, both with their z axis along the spin axis a = z_i
/// (the markers of the bearing's revolute joint). With the relative spin
/// omega = a . (w_j - w_i) and the commanded torque T = max(0, torque(t)):
///   m_j = -T tanh(omega / omega_s) a,  m_i = -m_j,  no forces,
/// i.e. dry friction of magnitude T regularised over |omega| ~ omega_s: it
/// vanishes at zero spin (no chatter at standstill) and, below omega_s,
/// acts as a viscous damper of coefficient T / omega_s. K and C are analytic
/// (a fixed in marker i: da = -skew(a) dtheta_i).
class WheelBrake final : public ForceElement {
 public:
  /// `torque` [N m] (function of time) must not be null and the smoothing
  /// spin omega_s [rad/s] must be positive; throws InputError naming the
  /// element otherwise.
  WheelBrake(std::string name, std::shared_ptr<const ScalarFunction> torque, double smoothing_spin);
  const char* type() const override { return "wheel_brake"; }
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const override;
  /// Smoothing spin omega_s [rad/s].
  double smoothing_spin() const { return omega_s_; }

 private:
  std::shared_ptr<const ScalarFunction> torque_;
  double omega_s_;
};

}  // namespace flexmb::vehicle
