#include "flexmb/vehicle/wheel_brake.h"

#include <algorithm>
#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"

namespace flexmb::vehicle {

WheelBrake::WheelBrake(std::string name, std::shared_ptr<const ScalarFunction> torque, double smoothing_spin)
    : ForceElement(std::move(name)), torque_(std::move(torque)), omega_s_(smoothing_spin) {
  const ErrorContext ctx{"", 0, "wheel brake '" + this->name() + "'"};
  if (!torque_) throw InputError("needs a brake torque function", ctx);
  if (!(omega_s_ > 0) || !std::isfinite(omega_s_)) throw InputError("smoothing spin must be a positive number", ctx);
}

void WheelBrake::Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const {
  e.wrench.setZero();
  e.K.setZero();
  e.C.setZero();
  const double T = std::max(0.0, torque_->Value(t));
  if (T == 0.0) return;
  const Vec3 a = mi.R_WM.col(2);
  const Vec3 dw = mj.w_WM - mi.w_WM;
  const double omega = a.dot(dw);
  const double s = std::tanh(omega / omega_s_);
  const double ds = (1.0 - s * s) / omega_s_;
  const Vec3 mj_vec = -T * s * a;
  e.wrench.segment<3>(9) = mj_vec;
  e.wrench.segment<3>(3) = -mj_vec;
  // d omega / d dtheta_i = (a x dw)^T; da / d dtheta_i = -skew(a)
  const Mat3 Kj = -T * ds * a * a.cross(dw).transpose() + T * s * Skew(a);
  e.K.block<3, 3>(9, 3) = Kj;
  e.K.block<3, 3>(3, 3) = -Kj;
  const Mat3 Cj = -T * ds * a * a.transpose();
  e.C.block<3, 3>(9, 9) = Cj;
  e.C.block<3, 3>(9, 3) = -Cj;
  e.C.block<3, 3>(3, 9) = -Cj;
  e.C.block<3, 3>(3, 3) = Cj;
}

}  // namespace flexmb::vehicle
