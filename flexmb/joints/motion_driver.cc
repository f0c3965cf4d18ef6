#include "flexmb/joints/motion_driver.h"

#include <cmath>

namespace flexmb {

MotionDriver::MotionDriver(std::string name, const Joint* target, int coordinate,
                           std::shared_ptr<const ScalarFunction> f)
    : Joint(std::move(name)), target_(target), coordinate_(coordinate), f_(std::move(f)) {
  marker_i = target->marker_i;
  marker_j = target->marker_j;
}

std::string MotionDriver::EquationName(int) const {
  return std::string(target_->CoordinateName(coordinate_)) + " of joint '" + target_->name() +
         "' = f(t)";
}

void MotionDriver::Evaluate(const MarkerState& mi, const MarkerState& mj, double t,
                            JointEval& e) const {
  Vec12 dq;
  const double c = target_->Coordinate(coordinate_, mi, mj, &dq);
  double r = c - f_->Value(t);
  if (target_->CoordinateIsAngle(coordinate_)) r = std::remainder(r, 2.0 * M_PI);
  e.phi(0) = r;
  e.phi_t(0) = -f_->Derivative(t);
  e.D.row(0) = dq.transpose();
}

MarkerState PerturbMarker(const MarkerState& m, int k, double eps) {
  MarkerState p;  // pose only: J stays empty, so no allocation
  p.p_WM = m.p_WM;
  p.R_WM = m.R_WM;
  if (k < 3) {
    p.p_WM(k) += eps;
  } else {
    Vec3 th = Vec3::Zero();
    th(k - 3) = eps;
    p.R_WM = ExpSO3(th) * m.R_WM;
  }
  return p;
}

void MotionDriver::AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj,
                                         const double* lambda, Mat12& H) const {
  const double h = 1e-6;
  Vec12 dp, dm;
  for (int k = 0; k < 12; ++k) {
    const bool on_i = k < 6;
    const MarkerState ip = PerturbMarker(mi, on_i ? k : 0, on_i ? h : 0.0);
    const MarkerState jp = PerturbMarker(mj, on_i ? 0 : k - 6, on_i ? 0.0 : h);
    const MarkerState im = PerturbMarker(mi, on_i ? k : 0, on_i ? -h : 0.0);
    const MarkerState jm = PerturbMarker(mj, on_i ? 0 : k - 6, on_i ? 0.0 : -h);
    target_->Coordinate(coordinate_, ip, jp, &dp);
    target_->Coordinate(coordinate_, im, jm, &dm);
    H.col(k) += lambda[0] * (dp - dm) / (2 * h);
  }
}

}  // namespace flexmb
