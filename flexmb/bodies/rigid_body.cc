#include "flexmb/bodies/rigid_body.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb {

Mat3 InertiaAboutCom(double mass, const Mat3& I_F, const Vec3& p_BF, const Mat3& R_BF,
                     const Vec3& c_B) {
  // rotate to body axes (still about the origin of F), then parallel axis theorem
  const Mat3 I_P = R_BF * I_F * R_BF.transpose();
  const Vec3 r = c_B - p_BF;
  return I_P - mass * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
}

RigidBody::RigidBody(std::string name, const RigidBodyData& data) : Body(std::move(name)), data_(data) {
  const ErrorContext ctx{"", 0, "body '" + this->name() + "'"};
  if (!(data_.mass > 0.0) || !std::isfinite(data_.mass))
    throw InputError("mass must be positive and finite, got " + std::to_string(data_.mass), ctx);
  const Mat3& I = data_.inertia_C;
  if (!I.allFinite()) throw InputError("inertia has non-finite entries", ctx);
  if ((I - I.transpose()).norm() > 1e-12 * std::max(1.0, I.norm()))
    throw InputError("inertia tensor is not symmetric", ctx);
  Eigen::SelfAdjointEigenSolver<Mat3> es(I);
  const Vec3 e = es.eigenvalues();
  if (!(e.minCoeff() > 0.0))
    throw InputError("inertia about the centre of mass is not positive definite (principal moments " +
                         std::to_string(e(0)) + ", " + std::to_string(e(1)) + ", " +
                         std::to_string(e(2)) + " kg m^2)",
                     ctx);
  const double tol = 1e-9 * e.sum();
  if (e(0) + e(1) < e(2) - tol)
    throw InputError("principal moments violate the triangle inequality I1 + I2 >= I3", ctx);
}

void RigidBody::InitialCoordinates(double* q, double* v) const {
  const Vec3 p_WC = data_.p_WB + data_.R_WB * data_.c_B;
  const Quat quat(data_.R_WB);
  q[0] = p_WC.x(), q[1] = p_WC.y(), q[2] = p_WC.z();
  q[3] = quat.w(), q[4] = quat.x(), q[5] = quat.y(), q[6] = quat.z();
  const Vec3 v_WC = data_.v_WB + data_.w_WB.cross(data_.R_WB * data_.c_B);
  const Vec3 w_B = data_.R_WB.transpose() * data_.w_WB;
  for (int k = 0; k < 3; ++k) v[k] = v_WC(k), v[3 + k] = w_B(k);
}

void RigidBody::Retract(const double* q, const double* dx, double* q_out) const {
  for (int k = 0; k < 3; ++k) q_out[k] = q[k] + dx[k];
  Quat r = BodyQuat(q) * ExpQuat(Vec3(dx[3], dx[4], dx[5]));
  r.normalize();
  q_out[3] = r.w(), q_out[4] = r.x(), q_out[5] = r.y(), q_out[6] = r.z();
}

void RigidBody::MassMatrix(const double*, MatX& M) const {
  M.setZero(6, 6);
  M.topLeftCorner<3, 3>().diagonal().setConstant(data_.mass);
  M.bottomRightCorner<3, 3>() = data_.inertia_C;
}

void RigidBody::AddForces(const double*, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q,
                          Eigen::Ref<MatX>, Eigen::Ref<MatX> dQdv) const {
  const Vec3 w(v[3], v[4], v[5]);
  const Vec3 Jw = data_.inertia_C * w;
  // gravity at the centre of mass; gyroscopic moment -w x (J w)
  Q.head<3>() += data_.mass * g_W;
  Q.tail<3>() -= w.cross(Jw);
  dQdv.bottomRightCorner<3, 3>() += Skew(Jw) - Skew(w) * data_.inertia_C;
}

void RigidBody::EvaluateMarker(const double* q, const double* v, const Marker& m,
                               MarkerState& out) const {
  const Mat3 R = BodyQuat(q).toRotationMatrix();
  const Vec3 s_W = R * m.p_BM;
  const Vec3 w_W = R * Vec3(v[3], v[4], v[5]);
  out.p_WM = Vec3(q[0], q[1], q[2]) + s_W;
  out.R_WM = R * m.R_BM;
  out.v_WM = Vec3(v[0], v[1], v[2]) + w_W.cross(s_W);
  out.w_WM = w_W;
  out.J.resize(6, 6);
  out.J.setZero();
  out.J.topLeftCorner<3, 3>().setIdentity();
  out.J.topRightCorner<3, 3>() = -R * Skew(m.p_BM);
  out.J.bottomRightCorner<3, 3>() = R;
  out.v_offset = v_offset;
  out.nv = 6;
}

Vec6 RigidBody::MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const {
  const Mat3 R = BodyQuat(q).toRotationMatrix();
  const Vec3 w(v[3], v[4], v[5]);
  Vec6 b;
  b.head<3>() = R * w.cross(w.cross(m.p_BM));
  b.tail<3>().setZero();
  return b;
}

void RigidBody::AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                                       Eigen::Ref<MatX> dQdq) const {
  // (J^T w)_rot = skew(s) R^T f + R^T m; d(R^T x)/dtheta_B = skew(R^T x)
  const Mat3 Rt = BodyQuat(q).toRotationMatrix().transpose();
  const Vec3 f_B = Rt * wrench_W.head<3>();
  const Vec3 m_B = Rt * wrench_W.tail<3>();
  dQdq.bottomRightCorner<3, 3>() += Skew(m.p_BM) * Skew(f_B) + Skew(m_B);
}

void RigidBody::MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                                   Eigen::Ref<MatX> out) const {
  // v_M = v_C + R (w x s), w_W = R w; R <- R exp(dtheta)
  const Mat3 R = BodyQuat(q).toRotationMatrix();
  const Vec3 w(v[3], v[4], v[5]);
  out.setZero();
  out.block<3, 3>(0, 3) = -R * Skew(w.cross(m.p_BM));
  out.block<3, 3>(3, 3) = -R * Skew(w);
}

double RigidBody::KineticEnergy(const double*, const double* v) const {
  const Vec3 vc(v[0], v[1], v[2]), w(v[3], v[4], v[5]);
  return 0.5 * data_.mass * vc.squaredNorm() + 0.5 * w.dot(data_.inertia_C * w);
}

double RigidBody::GravityPotential(const double* q, const Vec3& g_W) const {
  return -data_.mass * g_W.dot(Vec3(q[0], q[1], q[2]));
}

Vec6 RigidBody::Momentum(const double* q, const double* v) const {
  const Vec3 p(q[0], q[1], q[2]), vc(v[0], v[1], v[2]), w(v[3], v[4], v[5]);
  const Mat3 R = BodyQuat(q).toRotationMatrix();
  Vec6 h;
  h.head<3>() = data_.mass * vc;
  h.tail<3>() = p.cross(data_.mass * vc) + R * (data_.inertia_C * w);
  return h;
}

void RigidBody::BodyFramePose(const double* q, Vec3& p_WB, Mat3& R_WB) const {
  R_WB = BodyQuat(q).toRotationMatrix();
  p_WB = Vec3(q[0], q[1], q[2]) - R_WB * data_.c_B;
}

}  // namespace flexmb
