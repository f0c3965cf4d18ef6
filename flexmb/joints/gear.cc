#include "flexmb/joints/gear.h"

#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/joints/motion_driver.h"

namespace flexmb {
namespace {

// angle of direction z (fixed in the other shaft's carrier) in the xy plane
// of frame (x, y) and its derivatives with respect to the rotation of that
// frame (d_frame) and of z (d_dir); false when z is along the frame's z axis
bool GearDirectionAngle(const Vec3& x, const Vec3& y, const Vec3& z, double* angle, Vec3* d_frame, Vec3* d_dir) {
  const double u = z.dot(y), w = z.dot(x);
  const double rho2 = u * u + w * w;
  if (!(rho2 > 1e-12)) return false;
  // du = dth_f . (y x z) + dth_z . (z x y), dw likewise with x
  const Vec3 g = (w * y - u * x).cross(z) / rho2;
  *d_frame = g;
  *d_dir = -g;
  *angle = std::atan2(u, w);
  return true;
}

}  // namespace

GearJoint::GearJoint(std::string name, double ratio) : Joint(std::move(name)), ratio_(ratio) {
  if (!(ratio != 0.0) || !std::isfinite(ratio))
    throw InputError("gear ratio must be a non-zero number", {"", 0, "joint '" + this->name() + "'"});
}

std::string GearJoint::EquationName(int) const { return "theta_i - ratio theta_j = 0"; }

Eigen::Vector2d GearJoint::ShaftAngles(const MarkerState& mi, const MarkerState& mj) {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  return Eigen::Vector2d(-std::atan2(Rj.col(2).dot(Ri.col(1)), Rj.col(2).dot(Ri.col(0))),
              -std::atan2(Ri.col(2).dot(Rj.col(1)), Ri.col(2).dot(Rj.col(0))));
}

double GearJoint::Phi(const MarkerState& mi, const MarkerState& mj, Vec12* d) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  Vec3 ai_i, ai_j, bj_j, bj_i;
  double alpha = 0.0, beta = 0.0;
  if (!GearDirectionAngle(Ri.col(0), Ri.col(1), Rj.col(2), &alpha, &ai_i, &ai_j) ||
      !GearDirectionAngle(Rj.col(0), Rj.col(1), Ri.col(2), &beta, &bj_j, &bj_i))
    throw NumericalError("gear shaft axes are parallel", {"", 0, "joint '" + name() + "'"});
  // theta_i = -alpha, theta_j = -beta
  if (d) {
    d->setZero();
    d->segment<3>(3) = -ai_i + ratio_ * bj_i;
    d->segment<3>(9) = -ai_j + ratio_ * bj_j;
  }
  return std::remainder(-alpha + ratio_ * beta, 2.0 * M_PI);
}

void GearJoint::Evaluate(const MarkerState& mi, const MarkerState& mj, double, JointEval& e) const {
  Vec12 d;
  e.phi[0] = Phi(mi, mj, &d);
  e.phi_t[0] = 0.0;
  e.D.row(0) = d.transpose();
}

void GearJoint::AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                                      Mat12& H) const {
  const double h = 1e-6;
  Vec12 dp, dm;
  for (int k = 0; k < 12; ++k) {
    // translations do not enter
    if (k % 6 < 3) continue;
    const bool on_i = k < 6;
    const MarkerState ip = on_i ? PerturbMarker(mi, k, h) : mi, im = on_i ? PerturbMarker(mi, k, -h) : mi;
    const MarkerState jp = on_i ? mj : PerturbMarker(mj, k - 6, h), jm = on_i ? mj : PerturbMarker(mj, k - 6, -h);
    Phi(ip, jp, &dp);
    Phi(im, jm, &dm);
    H.col(k) += lambda[0] * (dp - dm) / (2 * h);
  }
}

}  // namespace flexmb
