#include "flexmb/forces/rotational_spring_damper.h"

#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/joints/constraint_primitives.h"

namespace flexmb {
RotationalSpringDamper::RotationalSpringDamper(std::string name, RotationalSpringDamperLaw law)
    : ForceElement(std::move(name)), law_(std::move(law)) {
  const ErrorContext ctx{"", 0, "force '" + this->name() + "'"};
  if (!std::isfinite(law_.stiffness) || law_.stiffness < 0.0)
    throw InputError("stiffness must be finite and >= 0, got " + std::to_string(law_.stiffness), ctx);
  if (!std::isfinite(law_.damping) || law_.damping < 0.0)
    throw InputError("damping must be finite and >= 0, got " + std::to_string(law_.damping), ctx);
  if (!std::isfinite(law_.angle0) || !std::isfinite(law_.preload))
    throw InputError("angle0 and preload must be finite", ctx);
}

void RotationalSpringDamper::Evaluate(const MarkerState& mi, const MarkerState& mj, double,
                                      ForceEval& e) const {
  const Vec3 xj = mj.R_WM.col(0);
  if (std::hypot(mi.R_WM.col(0).dot(xj), mi.R_WM.col(1).dot(xj)) < 1e-9)
    throw NumericalError("x_j is parallel to z_i: the relative angle is undefined",
                         {"", 0, "force '" + name() + "'"});
  Vec12 g;
  const double theta = primitives::RelativeAngle(mi, mj, &g);
  const double delta = std::remainder(theta - law_.angle0, 2.0 * M_PI);
  const Vec3 z = mi.R_WM.col(2);
  const Vec3 wrel = mj.w_WM - mi.w_WM;
  const double rate = z.dot(wrel);
  double spring, dspring;
  if (law_.torque_angle) {
    spring = law_.torque_angle->Value(delta);
    dspring = law_.torque_angle->Derivative(delta);
  } else {
    spring = law_.stiffness * delta;
    dspring = law_.stiffness;
  }
  const double T = -(spring + law_.preload + law_.damping * rate);
  e.wrench.setZero();
  e.wrench.segment<3>(3) = -T * z;
  e.wrench.segment<3>(9) = T * z;

  // dT/dx = -(dspring g + damping d(rate)/dx), d(rate)/dth_i = z x wrel
  Vec12 dT = -dspring * g;
  dT.segment<3>(3) -= law_.damping * z.cross(wrel);
  e.K.setZero();
  e.K.block<3, 12>(9, 0) = z * dT.transpose();
  e.K.block<3, 3>(9, 3) -= T * Skew(z);  // dz/dth_i = -skew(z)
  e.K.block<3, 12>(3, 0) = -e.K.block<3, 12>(9, 0);
  // dT/dw_j = -damping z, dT/dw_i = +damping z
  const Mat3 Cz = law_.damping * z * z.transpose();
  e.C.setZero();
  e.C.block<3, 3>(9, 9) = -Cz;
  e.C.block<3, 3>(9, 3) = Cz;
  e.C.block<3, 3>(3, 9) = Cz;
  e.C.block<3, 3>(3, 3) = -Cz;
}

double RotationalSpringDamper::PotentialEnergy(const MarkerState& mi, const MarkerState& mj,
                                               double) const {
  const double delta =
      std::remainder(primitives::RelativeAngle(mi, mj, nullptr) - law_.angle0, 2.0 * M_PI);
  const double spring = law_.torque_angle ? law_.torque_angle->IntegralFromZero(delta)
                                          : 0.5 * law_.stiffness * delta * delta;
  return spring + law_.preload * delta;
}

}  // namespace flexmb
