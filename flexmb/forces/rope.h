#pragma once
/// \file rope.h
/// Hoisting rope of a crane: a tension-only axial element between the boom
/// head (marker i: sheave or rope point) and the hook block (marker j),
/// reeved in `falls` parts of line, whose free length follows the winch.

#include <memory>

#include "flexmb/forces/force_element.h"
#include "flexmb/math/running_integral.h"
#include "flexmb/math/scalar_function.h"

namespace flexmb {

/// Properties and winch of a Rope.
struct RopeLaw {
  double axial_stiffness = 0.0;  ///< EA [N]: metallic area times rope modulus, > 0
  int falls = 1;                 ///< parts of line n the hook block hangs on, >= 1
  double damping_time = 0.0;     ///< material damping time beta [s], >= 0
  /// Unstretched rope length between sheave and hook block, all falls
  /// together [m]: L0 at t = 0 (with `hoist_speed`) or for all t (without).
  double free_length = 0.0;
  /// L0(t) [m] given directly; optional, replaces free_length and hoist_speed.
  std::shared_ptr<const ScalarFunction> free_length_function;
  /// Hoisting speed v_h(t) [m/s], rope reeled in positive; optional:
  /// L0(t) = free_length - integral of v_h from 0 to t.
  std::shared_ptr<const ScalarFunction> hoist_speed;
};

/// Tension-only rope between the origins of markers i and j. With
/// d = p_j - p_i, l = |d|, u = d / l, ldot = u . (v_j - v_i), n falls and
/// free length L0(t), the rope strain and tension are
///   eps = (n l - L0) / L0,   T = EA eps + beta EA d(eps)/dt   for eps > 0,
/// T clamped at 0 (the damping never makes the rope push), and T = 0 when
/// slack (eps <= 0). The hook block hangs on n parts, so the force n T acts
/// as f_i = +n T u on marker i and f_j = -n T u on marker j (pulling the
/// markers together); no moments. K and C are exact on each side of the
/// slack/taut switch (a kink at eps = 0, as in a tension-only truss).
/// L0 is L0(t) as given, or free_length minus the exact integral of the
/// hoisting speed (Gauss-Legendre, 5 points on panels of kHoistPanel fixed
/// in time: exact for speeds polynomial of degree <= 9 on each panel).
/// The partial sums of the hoisting speed are cached (results do not
/// depend on the order of calls), so one Rope with a hoisting speed must not
/// be evaluated from two threads at once.
/// Not modelled: rope mass and sag, the rope running over the sheave to the
/// drum (friction, bending), drum inertia.
class Rope final : public ForceElement {
 public:
  /// Width of the quadrature panels of the hoisting speed [s].
  static constexpr double kHoistPanel = RunningIntegral::kWinchPanel;

  /// Throws InputError naming the rope for EA <= 0, falls < 1, a negative
  /// damping time, or a free length L0(0) <= 0.
  Rope(std::string name, RopeLaw law);
  const char* type() const override { return "rope"; }
  /// Throws InputError naming the rope when L0(t) <= 0 (the winch has
  /// reeled in more rope than there is) and NumericalError when the marker
  /// origins coincide.
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const override;
  /// Elastic energy EA L0 eps^2 / 2 when stretched, 0 when slack [J].
  double PotentialEnergy(const MarkerState& mi, const MarkerState& mj, double t) const override;
  /// The rope's properties.
  const RopeLaw& law() const { return law_; }
  /// Free length L0(t) [m] and its rate dL0/dt [m/s] at time t [s]; throws
  /// as Evaluate when L0(t) <= 0.
  void FreeLength(double t, double& L0, double& L0dot) const;

 private:
  RopeLaw law_;
  PaidOutLength payout_;  // L0(t) from the law
};

}  // namespace flexmb
