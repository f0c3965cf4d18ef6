#include "flexmb/forces/joint_motor.h"

#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb {

JointMotor::JointMotor(std::string name, const Joint* joint, int coordinate,
                       std::shared_ptr<const ScalarFunction> function, JointMotorPd pd)
    : ForceElement(std::move(name)), joint_(joint), coordinate_(coordinate), f_(std::move(function)),
      pd_(std::move(pd)) {
  const ErrorContext ctx{"", 0, "force '" + this->name() + "'"};
  if (!joint_) throw InputError("joint motor without a joint", ctx);
  if (coordinate_ < 0 || coordinate_ >= joint_->NumCoordinates())
    throw InputError("joint '" + joint_->name() + "' (" + joint_->type() + ") has " +
                         std::to_string(joint_->NumCoordinates()) + " coordinate(s); coordinate " +
                         std::to_string(coordinate_) + " does not exist",
                     ctx);
  if (!f_ && !pd_.target) throw InputError("a joint motor needs a function or a PD target", ctx);
  if (!std::isfinite(pd_.kp) || !std::isfinite(pd_.kd) || pd_.kp < 0.0 || pd_.kd < 0.0)
    throw InputError("kp and kd must be finite and >= 0", ctx);
  angle_ = joint_->CoordinateIsAngle(coordinate_);
  marker_i = joint_->marker_i;
  marker_j = joint_->marker_j;
}

void JointMotor::Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const {
  const Vec3 a = joint_->CoordinateAxis(coordinate_, mi);
  const Vec3 d = mj.p_WM - mi.p_WM;
  double tau = f_ ? f_->Value(t) : 0.0;
  // derivatives of tau with respect to the poses and the twists
  Vec12 dtau = Vec12::Zero(), dtau_c = Vec12::Zero();
  if (pd_.target) {
    Vec12 g;
    const double c = joint_->Coordinate(coordinate_, mi, mj, &g);
    double err = pd_.target->Value(t) - c;
    if (angle_) err = std::remainder(err, 2.0 * M_PI);
    double rate;
    Vec12 drate = Vec12::Zero(), drate_c = Vec12::Zero();
    if (angle_) {
      const Vec3 wrel = mj.w_WM - mi.w_WM;
      rate = a.dot(wrel);
      drate.segment<3>(3) = a.cross(wrel);
      drate_c.segment<3>(3) = -a;
      drate_c.segment<3>(9) = a;
    } else {
      const Vec3 vrel = mj.v_WM - mi.v_WM;
      const Vec3 axd = a.cross(d);
      rate = a.dot(vrel) + axd.dot(mi.w_WM);
      drate.segment<3>(0) = -mi.w_WM.cross(a);
      drate.segment<3>(3) = a.cross(vrel) + a.cross(d.cross(mi.w_WM));
      drate.segment<3>(6) = mi.w_WM.cross(a);
      drate_c.segment<3>(0) = -a;
      drate_c.segment<3>(3) = axd;
      drate_c.segment<3>(6) = a;
    }
    tau += pd_.kp * err + pd_.kd * (pd_.target->Derivative(t) - rate);
    dtau = -pd_.kp * g - pd_.kd * drate;
    dtau_c = -pd_.kd * drate_c;
  }

  e.wrench.setZero();
  e.K.setZero();
  e.C.setZero();
  const Mat3 Sa = Skew(a);  // da = -skew(a) dth_i
  if (angle_) {
    e.wrench.segment<3>(3) = -tau * a;
    e.wrench.segment<3>(9) = tau * a;
    e.K.block<3, 12>(9, 0) = a * dtau.transpose();
    e.K.block<3, 3>(9, 3) -= tau * Sa;
    e.K.block<3, 12>(3, 0) = -e.K.block<3, 12>(9, 0);
    e.C.block<3, 12>(9, 0) = a * dtau_c.transpose();
    e.C.block<3, 12>(3, 0) = -e.C.block<3, 12>(9, 0);
  } else {
    const Vec3 axd = a.cross(d);
    e.wrench.segment<3>(0) = -tau * a;
    e.wrench.segment<3>(3) = tau * axd;
    e.wrench.segment<3>(6) = tau * a;
    e.K.block<3, 12>(6, 0) = a * dtau.transpose();
    e.K.block<3, 3>(6, 3) -= tau * Sa;
    e.K.block<3, 12>(0, 0) = -e.K.block<3, 12>(6, 0);
    // m_i = tau a x d: d(a x d) = skew(d) skew(a) dth_i + skew(a) (dp_j - dp_i)
    e.K.block<3, 12>(3, 0) = axd * dtau.transpose();
    e.K.block<3, 3>(3, 3) += tau * Skew(d) * Sa;
    e.K.block<3, 3>(3, 0) -= tau * Sa;
    e.K.block<3, 3>(3, 6) += tau * Sa;
    e.C.block<3, 12>(6, 0) = a * dtau_c.transpose();
    e.C.block<3, 12>(0, 0) = -e.C.block<3, 12>(6, 0);
    e.C.block<3, 12>(3, 0) = axd * dtau_c.transpose();
  }
}

}  // namespace flexmb
