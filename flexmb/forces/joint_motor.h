#pragma once
/// \file joint_motor.h
/// Actuator torque or force on a joint coordinate: a function of time and,
/// optionally, a PD controller towards a target motion.

#include <memory>

#include "flexmb/forces/force_element.h"
#include "flexmb/math/scalar_function.h"

namespace flexmb {

/// PD control law of a JointMotor: tau += kp (r(t) - c) + kd (r'(t) - cdot).
struct JointMotorPd {
  std::shared_ptr<const ScalarFunction> target;  ///< r(t) [rad or m]; null: no controller
  double kp = 0.0;  ///< proportional gain [N m/rad or N/m], >= 0
  double kd = 0.0;  ///< derivative gain [N m s/rad or N s/m], >= 0
};

/// Motor acting on coordinate `coordinate` of a joint, with the joint's
/// markers. tau = function(t) [+ PD law] is a torque [N m] for an angle
/// coordinate and a force [N] for a translation. The axis a is
/// Joint::CoordinateAxis (marker i's z axis for the built-in joints), taken to
/// be fixed in marker i.
///  - angle: m_j = tau a, m_i = -tau a; rate cdot = a . (w_j - w_i).
///  - translation: f_j = tau a, f_i = -tau a, m_i = tau a x d (d = p_j - p_i);
///    rate cdot = a . (v_j - v_i) + (a x d) . w_i (the exact derivative of a . d).
/// c is Joint::Coordinate; for angles r - c is wrapped to (-pi, pi]. The angle
/// rate equals dc/dt while the joint keeps z_i parallel to z_j.
class JointMotor final : public ForceElement {
 public:
  /// `function` may be null (no feed-forward). Throws InputError naming the
  /// element if the joint is null or has no coordinate `coordinate`, if
  /// neither a function nor a PD target is given, or a gain is negative.
  JointMotor(std::string name, const Joint* joint, int coordinate,
             std::shared_ptr<const ScalarFunction> function, JointMotorPd pd = {});
  const char* type() const override { return "joint_motor"; }
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const override;

  /// The actuated joint.
  const Joint* joint() const { return joint_; }
  /// The actuated coordinate of the joint.
  int coordinate() const { return coordinate_; }

 private:
  const Joint* joint_;
  int coordinate_;
  bool angle_;
  std::shared_ptr<const ScalarFunction> f_;
  JointMotorPd pd_;
};

}  // namespace flexmb
