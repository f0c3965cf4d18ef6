#include "flexmb/joints/constraint_primitives.h"

#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb::primitives {

// Variations: da = dth_i x a = -skew(a) dth_i; db = -skew(b) dth_j; dd = dp_j - dp_i.

void Perpendicular(const Vec3& a, const Vec3& b, JointEval& e, int row) {
  e.phi(row) = a.dot(b);
  const Vec3 axb = a.cross(b);
  auto D = e.D.row(row);
  D.setZero();
  D.segment<3>(3) = axb.transpose();   // d(a.b)/dth_i = a x b
  D.segment<3>(9) = -axb.transpose();  // d(a.b)/dth_j = b x a
}

void PerpendicularStiffness(const Vec3& a, const Vec3& b, double lambda, Mat12& H) {
  // d(a x b) = skew(b) skew(a) dth_i - skew(a) skew(b) dth_j
  const Mat3 Sa = Skew(a), Sb = Skew(b);
  const Mat3 Ai = lambda * Sb * Sa, Aj = -lambda * Sa * Sb;
  H.block<3, 3>(3, 3) += Ai;
  H.block<3, 3>(3, 9) += Aj;
  H.block<3, 3>(9, 3) -= Ai;
  H.block<3, 3>(9, 9) -= Aj;
}

void PointInPlane(const Vec3& a, const Vec3& d, JointEval& e, int row) {
  e.phi(row) = a.dot(d);
  auto D = e.D.row(row);
  D.setZero();
  D.segment<3>(0) = -a.transpose();
  D.segment<3>(3) = a.cross(d).transpose();
  D.segment<3>(6) = a.transpose();
}

void PointInPlaneStiffness(const Vec3& a, const Vec3& d, double lambda, Mat12& H) {
  // rows of D^T: (-a, a x d, a, 0)
  // d(-a) = skew(a) dth_i;  d(a x d) = skew(d) skew(a) dth_i + skew(a) (dp_j - dp_i)
  const Mat3 Sa = Skew(a), Sd = Skew(d);
  H.block<3, 3>(0, 3) += lambda * Sa;
  H.block<3, 3>(3, 3) += lambda * Sd * Sa;
  H.block<3, 3>(3, 0) -= lambda * Sa;
  H.block<3, 3>(3, 6) += lambda * Sa;
  H.block<3, 3>(6, 3) -= lambda * Sa;
}

void Distance(const Vec3& d, double length, JointEval& e, int row) {
  const double l = d.norm();
  if (l < 1e-12)
    throw NumericalError("distance constraint with coincident points: direction undefined");
  const Vec3 u = d / l;
  e.phi(row) = l - length;
  auto D = e.D.row(row);
  D.setZero();
  D.segment<3>(0) = -u.transpose();
  D.segment<3>(6) = u.transpose();
}

void DistanceStiffness(const Vec3& d, double lambda, Mat12& H) {
  const double l = d.norm();
  if (l < 1e-12) return;
  const Vec3 u = d / l;
  const Mat3 P = lambda * (Mat3::Identity() - u * u.transpose()) / l;  // du/dd
  H.block<3, 3>(0, 0) += P;
  H.block<3, 3>(0, 6) -= P;
  H.block<3, 3>(6, 0) -= P;
  H.block<3, 3>(6, 6) += P;
}

double RelativeAngle(const MarkerState& mi, const MarkerState& mj, Vec12* dq) {
  const Vec3 xi = mi.R_WM.col(0), yi = mi.R_WM.col(1), xj = mj.R_WM.col(0);
  const double c = xi.dot(xj), s = yi.dot(xj);
  if (dq) {
    // ds = dth_i.(y_i x x_j) + dth_j.(x_j x y_i); dc likewise with x_i
    const double r2 = c * c + s * s;
    const Vec3 ds_i = yi.cross(xj), dc_i = xi.cross(xj);
    dq->setZero();
    dq->segment<3>(3) = (c * ds_i - s * dc_i) / r2;
    dq->segment<3>(9) = -(c * ds_i - s * dc_i) / r2;
  }
  return std::atan2(s, c);
}

double AxialTranslation(const MarkerState& mi, const MarkerState& mj, Vec12* dq) {
  const Vec3 z = mi.R_WM.col(2), d = mj.p_WM - mi.p_WM;
  if (dq) {
    dq->setZero();
    dq->segment<3>(0) = -z;
    dq->segment<3>(3) = z.cross(d);
    dq->segment<3>(6) = z;
  }
  return z.dot(d);
}

}  // namespace flexmb::primitives
