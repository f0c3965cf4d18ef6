#pragma once
/// \file spring_damper.h
/// Translational spring-damper acting along the line between two marker
/// origins.

#include <memory>

#include "flexmb/forces/force_element.h"
#include "flexmb/math/scalar_function.h"

namespace flexmb {

/// Force laws of a SpringDamper. The spring force is stiffness * x, or
/// force_deflection(x) when that function is given, with the deflection
/// x = l - free_length [m]; the damper force is damping * ldot, or
/// force_velocity(ldot) when given, with ldot [m/s] the rate of the length.
/// Tension is positive.
struct SpringDamperLaw {
  double free_length = 0.0;  ///< length at which the spring force is `preload` [m], >= 0
  double stiffness = 0.0;    ///< linear stiffness [N/m] (used without force_deflection)
  double damping = 0.0;      ///< linear damping [N s/m] (used without force_velocity)
  double preload = 0.0;      ///< force at the free length, tension positive [N]
  std::shared_ptr<const ScalarFunction> force_deflection;  ///< F(x) [N], x [m]; optional
  std::shared_ptr<const ScalarFunction> force_velocity;    ///< F(ldot) [N], ldot [m/s]; optional
};

/// Spring-damper between the origins of markers i and j. With
/// d = p_j - p_i, l = |d|, u = d / l and ldot = u . (v_j - v_i), the tension
///   F = spring(l - free_length) + preload + damper(ldot)
/// acts as f_i = +F u on marker i and f_j = -F u on marker j (a positive F
/// pulls the markers together); no moments. Throws NumericalError when the
/// origins coincide (the direction is undefined; use a bushing instead).
class SpringDamper final : public ForceElement {
 public:
  /// Throws InputError naming the element for a negative or non-finite
  /// free length, stiffness or damping.
  SpringDamper(std::string name, SpringDamperLaw law);
  const char* type() const override { return "spring_damper"; }
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const override;
  /// 0.5 k x^2 + preload x for the linear spring; for force_deflection, the
  /// integral of F(s) from 0 to x (Simpson's rule, 64 intervals) plus
  /// preload x. The damper stores nothing. [J]
  double PotentialEnergy(const MarkerState& mi, const MarkerState& mj, double t) const override;
  /// The force laws.
  const SpringDamperLaw& law() const { return law_; }

 private:
  SpringDamperLaw law_;
};

}  // namespace flexmb
