#pragma once
/// \file motion_driver.h
/// Prescribed motion of a joint coordinate: a rheonomic constraint
/// c(q) - f(t) = 0 on coordinate k of another joint, with the same markers.

#include <memory>

#include "flexmb/joints/joint.h"
#include "flexmb/math/scalar_function.h"

namespace flexmb {

/// Drives coordinate `coordinate` of joint `target` along f(t) [rad or m].
/// For angles the difference c - f is wrapped to (-pi, pi], so the driven
/// joint may turn any number of revolutions.
class MotionDriver final : public Joint {
 public:
  MotionDriver(std::string name, const Joint* target, int coordinate,
               std::shared_ptr<const ScalarFunction> f);
  const char* type() const override { return "motion"; }
  int NumEquations() const override { return 1; }
  std::string EquationName(int k) const override;
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const override;
  /// Geometric stiffness by central differences of the analytic derivative
  /// (one equation, 12 evaluations).
  void AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                             Mat12& H) const override;

  /// The driven joint.
  const Joint* target() const { return target_; }
  /// The driving function of time.
  const ScalarFunction& function() const { return *f_; }

 private:
  const Joint* target_;
  int coordinate_;
  std::shared_ptr<const ScalarFunction> f_;
};

/// Returns `m` moved by the variation eps * e_k, k in 0..5 (dp then dtheta,
/// world components). Only the pose is set (J stays empty). Used for
/// finite-difference derivatives.
MarkerState PerturbMarker(const MarkerState& m, int k, double eps);

}  // namespace flexmb
