#pragma once
/// \file winch_driver.h
/// Winch of a hoisting rope of changing length (ancf/ancf_hoist_rope_body.h):
/// prescribes the rope's free length L(t) through its payout marker.

#include <memory>

#include "flexmb/joints/joint.h"
#include "flexmb/math/running_integral.h"
#include "flexmb/math/scalar_function.h"

namespace flexmb {

/// How a WinchDriver moves the rope.
struct WinchLaw {
  double free_length = 0.0;  ///< L(0) [m], > 0 (with `hoist_speed`, or alone: L held)
  /// Hoisting speed v_h(t) [m/s], rope hauled in positive: L(t) = free_length
  /// - int_0^t v_h. Optional.
  std::shared_ptr<const ScalarFunction> hoist_speed;
  /// L(t) [m] given directly; optional, replaces free_length and hoist_speed.
  std::shared_ptr<const ScalarFunction> free_length_function;
};

/// One equation between marker i, the rope's payout marker (at (L, 0, 0) in
/// world), and marker j, a ground marker at the world origin:
/// phi = x_i - x_j - L_ref(t). The multiplier is the rope's pull on the drum
/// line (the drum torque divided by the winding radius) [N]; as for every
/// joint, the reaction on marker j (a joint_reaction sensor) is that pull
/// along world x. The hoisting speed
/// is integrated as in Rope (RunningIntegral, panels of kWinchPanel),
/// so one driver must not be evaluated from two threads at once.
class WinchDriver final : public Joint {
 public:
  /// Throws InputError naming the driver when both a function and a
  /// hoisting speed are given, or L_ref(0) <= 0.
  WinchDriver(std::string name, WinchLaw law);
  const char* type() const override { return "winch"; }
  int NumEquations() const override { return 1; }
  std::string EquationName(int k) const override;
  /// Throws NumericalError naming the driver when L_ref(t) <= 0 (the winch
  /// hauled in more rope than hangs).
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const override;
  /// Nothing: the equation is linear in the marker position.
  void AddGeometricStiffness(const MarkerState&, const MarkerState&, const double*, Mat12&) const override {}
  /// L_ref(t) [m] and its rate [m/s].
  void FreeLength(double t, double& L, double& Ldot) const;

 private:
  WinchLaw law_;
  PaidOutLength payout_;  // L_ref(t) from the law
};

}  // namespace flexmb
