#include "flexmb/bodies/flexible_body.h"

#include <algorithm>
#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/reduction/inertia_invariants.h"

namespace flexmb {
namespace {


// the reduced body, checked before the members that refer to it are built
const reduction::InertiaInvariants& CheckedInvariants(const std::string& name, const FlexibleBodyData& d) {
  const ErrorContext ctx{"", 0, "flexible body '" + name + "'"};
  if (!d.reduced) throw InputError("no reduced body given", ctx);
  const reduction::ReducedBody& b = *d.reduced;
  const reduction::InertiaInvariants& inv = b.invariants;
  const int n = inv.n;
  const auto nn = static_cast<size_t>(n);
  const auto wrong = [&](const std::string& what) {
    throw InputError("inconsistent reduced body: " + what + " (" + std::to_string(n) + " modes)", ctx);
  };
  if (n < 0) wrong("negative number of modes");
  if (inv.mvo1.size() != nn || inv.moo1.size() != nn || inv.moo2.size() != nn * nn || inv.mow1.size() != nn)
    wrong("invariant lists have the wrong length");
  if (inv.mvw.rows() != 3 || inv.mvw.cols() != n || inv.mow0.rows() != 3 || inv.mow0.cols() != n ||
      inv.mww.rows() != n || inv.mww.cols() != n)
    wrong("invariant blocks have the wrong size");
  for (const MatX& m : inv.mow1) {
    if (m.rows() != 3 || m.cols() != n) wrong("mow1 blocks have the wrong size");
  }
  if (b.modes.rows() != 6 * static_cast<Eigen::Index>(b.mesh.nodes.size()) || b.modes.cols() != n)
    wrong("mode matrix is not 6 x nodes by modes");
  if (b.stiffness.rows() != n || b.stiffness.cols() != n) wrong("stiffness is not n x n");
  if (b.damping.size() != 0 && (b.damping.rows() != n || b.damping.cols() != n)) wrong("damping is not n x n");
  if (d.damping.size() != 0 && (d.damping.rows() != n || d.damping.cols() != n))
    throw InputError("damping override is not " + std::to_string(n) + " x " + std::to_string(n), ctx);
  if (d.w0.size() != 0 && d.w0.size() != n) wrong("initial modal coordinates have the wrong length");
  if (d.wd0.size() != 0 && d.wd0.size() != n) wrong("initial modal velocities have the wrong length");
  if (!(inv.mvv.trace() > 0.0)) throw InputError("reduced body has no mass", ctx);
  return inv;
}

}  // namespace

FlexibleBody::FlexibleBody(std::string name, FlexibleBodyData data)
    : Body(std::move(name)),
      data_(std::move(data)),
      n_(CheckedInvariants(this->name(), data_).n),
      inertia_(data_.reduced->invariants),
      mass_tangent_(data_.reduced->invariants, inertia_) {
  if (data_.damping.size() != 0) {
    damping_ = data_.damping;
  } else if (data_.reduced->damping.size() != 0) {
    damping_ = data_.reduced->damping;
  } else {
    damping_.setZero(n_, n_);
  }
  const Mat3& s = data_.reduced->invariants.mvo0;  // -skew(S0)
  first_moment_ = Vec3(-s(2, 1), -s(0, 2), -s(1, 0));
  Hm_.setZero(3, n_);
  mass_rows_.setZero(3, 6 + n_);
  mass_cols_.setZero(6 + n_, 3);
  mass_body_.setZero(6 + n_, 6 + n_);
  theta_cols_.setZero(6 + n_, 3);
  nu_.setZero(6 + n_);
  stiffening_ = MakeGeometricStiffening(this->name(), *data_.reduced, data_.geometric_stiffening);
  deformation_stiffening_ =
      MakeDeformationStiffening(this->name(), *data_.reduced, data_.deformation_stiffening);
  const auto diagonal = [](const MatX& a) {
    MatX off = a;
    off.diagonal().setZero();
    return (off.array() == 0.0).all();
  };
  if (diagonal(data_.reduced->stiffness)) stiffness_diag_ = data_.reduced->stiffness.diagonal();
  if (diagonal(damping_)) damping_diag_ = damping_.diagonal();
}

void FlexibleBody::AddElasticAndDamping(const double* w, const double* wd, Eigen::Ref<VecX> Q) const {
  const Eigen::Map<const VecX> wv(w, n_), wdv(wd, n_);
  if (stiffness_diag_.size() == n_ && n_ > 0)
    Q.tail(n_).array() -= stiffness_diag_.array() * wv.array();
  else
    Q.tail(n_).noalias() -= data_.reduced->stiffness * wv;
  if (damping_diag_.size() == n_ && n_ > 0)
    Q.tail(n_).array() -= damping_diag_.array() * wdv.array();
  else
    Q.tail(n_).noalias() -= damping_ * wdv;
}

void FlexibleBody::UseMarkerNodes(const std::vector<int>& nodes) {
  const MatX& H = data_.reduced->modes;
  const int nn = static_cast<int>(data_.reduced->mesh.nodes.size());
  marker_slot_.assign(static_cast<size_t>(nn), -1);
  int count = 0;
  for (int node : nodes)
    if (node >= 0 && node < nn && marker_slot_[static_cast<size_t>(node)] < 0)
      marker_slot_[static_cast<size_t>(node)] = count++;
  marker_modes_.resize(6 * count, n_);
  for (int node = 0; node < nn && count > 0; ++node) {
    const int slot = marker_slot_[static_cast<size_t>(node)];
    if (slot >= 0) marker_modes_.middleRows(6 * slot, 6) = H.middleRows(6 * node, 6);
  }
}

Eigen::Block<const MatX, 3, Eigen::Dynamic> FlexibleBody::ModeRows(int node, int first) const {
  const int slot = node >= 0 && node < static_cast<int>(marker_slot_.size()) ? marker_slot_[static_cast<size_t>(node)] : -1;
  if (slot >= 0) return Eigen::Block<const MatX, 3, Eigen::Dynamic>(marker_modes_, 6 * slot + first, 0, 3, n_);
  return Eigen::Block<const MatX, 3, Eigen::Dynamic>(data_.reduced->modes, 6 * node + first, 0, 3, n_);
}

Eigen::Block<const MatX, 3, Eigen::Dynamic> FlexibleBody::Ht(int node) const { return ModeRows(node, 0); }

Eigen::Block<const MatX, 3, Eigen::Dynamic> FlexibleBody::Hr(int node) const { return ModeRows(node, 3); }

bool FlexibleBody::IsInterfaceNode(int node) const {
  const auto& in = data_.reduced->interface_nodes;
  if (std::find(in.begin(), in.end(), node) != in.end()) return true;
  // a node clamped in the reduction (--fix) has no modal motion: it is the
  // floating frame itself
  const MatX& H = data_.reduced->modes;
  return node >= 0 && 6 * static_cast<Eigen::Index>(node) + 6 <= H.rows() &&
         H.middleRows(6 * static_cast<Eigen::Index>(node), 6).isZero(0.0);
}

void FlexibleBody::MarkerGeometry(const Marker& m, const double* w, Vec3& s, Vec3& theta) const {
  const Eigen::Map<const VecX> wv(w, n_);
  if (m.node < 0) {
    Hm_.setZero();
    s = m.p_BM;
    theta.setZero();
    return;
  }
  if (m.node >= static_cast<int>(data_.reduced->mesh.nodes.size()))
    throw InputError("marker node index " + std::to_string(m.node) + " out of range",
                     {"", 0, "marker '" + m.name + "' on flexible body '" + name() + "'"});
  Hm_ = Ht(m.node);
  Hm_.noalias() -= Skew(m.p_BM) * Hr(m.node);
  s = data_.reduced->mesh.nodes[m.node].x + m.p_BM;
  s.noalias() += Hm_ * wv;
  theta.noalias() = Hr(m.node) * wv;
}

void FlexibleBody::MarkerBodyTwist(const double* v, const Marker& m, const Vec3& s, Vec3& v_rel,
                                   Vec3& w_B) const {
  const Vec3 om(v[3], v[4], v[5]);
  const Eigen::Map<const VecX> wd(v + 6, n_);
  v_rel = om.cross(s);
  v_rel.noalias() += Hm_ * wd;
  w_B = om;
  if (m.node >= 0) w_B.noalias() += Hr(m.node) * wd;
}

void FlexibleBody::InitialCoordinates(double* q, double* v) const {
  const Quat quat(data_.R_WB);
  for (int k = 0; k < 3; ++k) q[k] = data_.p_WB(k);
  q[3] = quat.w(), q[4] = quat.x(), q[5] = quat.y(), q[6] = quat.z();
  const Vec3 w_B = data_.R_WB.transpose() * data_.w_WB;
  for (int k = 0; k < 3; ++k) v[k] = data_.v_WB(k), v[3 + k] = w_B(k);
  for (int i = 0; i < n_; ++i) {
    q[7 + i] = data_.w0.size() ? data_.w0(i) : 0.0;
    v[6 + i] = data_.wd0.size() ? data_.wd0(i) : 0.0;
  }
}

void FlexibleBody::Retract(const double* q, const double* dx, double* q_out) const {
  for (int k = 0; k < 3; ++k) q_out[k] = q[k] + dx[k];
  Quat r = BodyQuat(q) * ExpQuat(Vec3(dx[3], dx[4], dx[5]));
  r.normalize();
  q_out[3] = r.w(), q_out[4] = r.x(), q_out[5] = r.y(), q_out[6] = r.z();
  for (int i = 0; i < n_; ++i) q_out[7 + i] = q[7 + i] + dx[6 + i];
}

void FlexibleBody::MassMatrix(const double* q, MatX& M) const {
  const int N = 6 + n_;
  if (M.rows() != N || M.cols() != N) M.resize(N, N);
  inertia_.MassMatrix(q + 7, M);
  // M_W = T^T M_B T with nu_B = T nu_W, T = diag(R^T, I, I)
  const Mat3 R = BodyQuat(q).toRotationMatrix();
  mass_rows_.noalias() = R * M.topRows<3>();
  M.topRows<3>() = mass_rows_;
  mass_cols_.noalias() = M.leftCols<3>() * R.transpose();
  M.leftCols<3>() = mass_cols_;
}

void FlexibleBody::AddForces(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q,
                             Eigen::Ref<MatX> dQdq, Eigen::Ref<MatX> dQdv) const {
  const int n = n_, N = 6 + n_;
  const Mat3 R = BodyQuat(q).toRotationMatrix();
  const Vec3 vW(v[0], v[1], v[2]), om(v[3], v[4], v[5]);
  const Vec3 vb = R.transpose() * vW, gb = R.transpose() * g_W;
  inertia_.Evaluate(vb, om, q + 7, v + 6, gb, true);
  const VecX& F = inertia_.F();
  const MatX& K = data_.reduced->stiffness;

  // forces: v rows turned to world
  Q.head<3>() += R * F.head<3>();
  Q.segment(3, N - 3) += F.tail(N - 3);
  AddElasticAndDamping(q + 7, v + 6, Q);

  // d/dv: columns (v_W, om, wd); vb = R^T v_W
  const auto& Fvb = inertia_.dF_dvb();
  const auto& Fom = inertia_.dF_dom();
  const MatX& Fwd = inertia_.dF_dwd();
  dQdv.block<3, 3>(0, 0) += R * Fvb.topRows<3>() * R.transpose();
  dQdv.block(3, 0, N - 3, 3).noalias() += Fvb.bottomRows(N - 3) * R.transpose();
  dQdv.block<3, 3>(0, 3) += R * Fom.topRows<3>();
  dQdv.block(3, 3, N - 3, 3) += Fom.bottomRows(N - 3);
  dQdv.block(0, 6, 3, n).noalias() += R * Fwd.topRows<3>();
  dQdv.block(3, 6, N - 3, n) += Fwd.bottomRows(N - 3);
  dQdv.bottomRightCorner(n, n) -= damping_;

  // d/dx: dtheta acts through vb, gb (d(R^T a)/dtheta = skew(R^T a)) and
  // through R in front of the v rows; dw directly
  theta_cols_.noalias() = Fvb * Skew(vb);
  theta_cols_.noalias() += inertia_.dF_dgb() * Skew(gb);
  dQdq.block<3, 3>(0, 3) += R * (theta_cols_.topRows<3>() - Skew(F.head<3>()));
  dQdq.block(3, 3, N - 3, 3) += theta_cols_.bottomRows(N - 3);
  const MatX& Fw = inertia_.dF_dw();
  dQdq.block(0, 6, 3, n).noalias() += R * Fw.topRows<3>();
  dQdq.block(3, 6, N - 3, n) += Fw.bottomRows(N - 3);
  dQdq.bottomRightCorner(n, n) -= K;
  if (stiffening_) stiffening_->Add(om, q + 7, Q.tail(n), dQdv.block(6, 3, n, 3), dQdq.bottomRightCorner(n, n));
  if (deformation_stiffening_) deformation_stiffening_->Add(q + 7, Q.tail(n), dQdq.bottomRightCorner(n, n));
}

bool FlexibleBody::AddForceVector(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q) const {
  const int n = n_, N = 6 + n_;
  const Mat3 R = BodyQuat(q).toRotationMatrix();
  const Vec3 vW(v[0], v[1], v[2]), om(v[3], v[4], v[5]);
  inertia_.Evaluate(R.transpose() * vW, om, q + 7, v + 6, R.transpose() * g_W, false);
  const VecX& F = inertia_.F();
  Q.head<3>() += R * F.head<3>();
  Q.segment(3, N - 3) += F.tail(N - 3);
  AddElasticAndDamping(q + 7, v + 6, Q);
  if (stiffening_) {
    // -G(om) w, G in the mass scratch
    auto G = mass_body_.topLeftCorner(n, n);
    stiffening_->Matrix(om, G);
    Q.tail(n).noalias() -= G * Eigen::Map<const VecX>(q + 7, n);
  }
  if (deformation_stiffening_) deformation_stiffening_->Add(q + 7, Q.tail(n));
  return true;
}

void FlexibleBody::AddMassTangent(const double* q, const double* a, double scale, Eigen::Ref<MatX> K) const {
  mass_tangent_.Add(BodyQuat(q).toRotationMatrix(), q + 7, a, scale, K);
}

void FlexibleBody::EvaluateMarker(const double* q, const double* v, const Marker& m,
                                  MarkerState& out) const {
  const int n = n_;
  Vec3 s, theta;
  MarkerGeometry(m, q + 7, s, theta);
  const Mat3 R = BodyQuat(q).toRotationMatrix();
  Vec3 ws, wn;
  MarkerBodyTwist(v, m, s, ws, wn);
  out.p_WM = Vec3(q[0], q[1], q[2]) + R * s;
  out.R_WM = R * ExpSO3(theta) * m.R_BM;
  out.v_WM = Vec3(v[0], v[1], v[2]) + R * ws;
  out.w_WM = R * wn;
  out.J.resize(6, 6 + n);
  out.J.setZero();
  out.J.topLeftCorner<3, 3>().setIdentity();
  out.J.block<3, 3>(0, 3) = -R * Skew(s);
  out.J.block<3, 3>(3, 3) = R;
  if (m.node >= 0) {
    out.J.block(0, 6, 3, n).noalias() = R * Hm_;
    out.J.block(3, 6, 3, n).noalias() = R * Hr(m.node);
  }
  out.v_offset = v_offset;
  out.nv = 6 + n;
}

Vec6 FlexibleBody::MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const {
  Vec3 s, theta;
  MarkerGeometry(m, q + 7, s, theta);
  const Mat3 R = BodyQuat(q).toRotationMatrix();
  const Vec3 om(v[3], v[4], v[5]);
  const Eigen::Map<const VecX> wd(v + 6, n_);
  Vec3 hwd = Hm_ * wd;
  Vec3 rwd = Vec3::Zero();
  if (m.node >= 0) rwd.noalias() = Hr(m.node) * wd;
  Vec6 b;
  b.head<3>() = R * (om.cross(om.cross(s)) + 2.0 * om.cross(hwd));
  b.tail<3>() = R * om.cross(rwd);
  return b;
}

void FlexibleBody::AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                                          Eigen::Ref<MatX> dQdq) const {
  // (J^T w): om rows skew(s) f_B + m_B, w rows Hm^T f_B + Hr^T m_B
  const int n = n_;
  Vec3 s, theta;
  MarkerGeometry(m, q + 7, s, theta);
  const Mat3 Rt = BodyQuat(q).toRotationMatrix().transpose();
  const Vec3 f_B = Rt * wrench_W.head<3>();
  const Vec3 m_B = Rt * wrench_W.tail<3>();
  const Mat3 Sf = Skew(f_B), Sm = Skew(m_B);
  dQdq.block<3, 3>(3, 3) += Skew(s) * Sf + Sm;
  if (m.node < 0) return;
  dQdq.block(3, 6, 3, n).noalias() -= Sf * Hm_;
  dQdq.block(6, 3, n, 3).noalias() += Hm_.transpose() * Sf;
  dQdq.block(6, 3, n, 3).noalias() += Hr(m.node).transpose() * Sm;
}

void FlexibleBody::MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                                      Eigen::Ref<MatX> out) const {
  const int n = n_;
  Vec3 s, theta;
  MarkerGeometry(m, q + 7, s, theta);
  const Mat3 R = BodyQuat(q).toRotationMatrix();
  const Vec3 om(v[3], v[4], v[5]);
  Vec3 y, wn;
  MarkerBodyTwist(v, m, s, y, wn);
  out.setZero();
  out.block<3, 3>(0, 3) = -R * Skew(y);
  out.block<3, 3>(3, 3) = -R * Skew(wn);
  if (m.node >= 0) out.block(0, 6, 3, n).noalias() = (R * Skew(om)) * Hm_;
}

double FlexibleBody::KineticEnergy(const double* q, const double* v) const {
  MassMatrix(q, mass_body_);
  const Eigen::Map<const VecX> nu(v, 6 + n_);
  nu_.noalias() = mass_body_ * nu;
  return 0.5 * nu.dot(nu_);
}

double FlexibleBody::GravityPotential(const double* q, const Vec3& g_W) const {
  const Mat3 R = BodyQuat(q).toRotationMatrix();
  const double m = data_.reduced->invariants.mvv.trace() / 3.0;
  Vec3 S = first_moment_;
  S.noalias() += data_.reduced->invariants.mvw * Eigen::Map<const VecX>(q + 7, n_);
  return -g_W.dot(m * Vec3(q[0], q[1], q[2]) + R * S);
}

Vec6 FlexibleBody::Momentum(const double* q, const double* v) const {
  // world-velocity mass matrix: rows 0-2 are R p_v, rows 3-5 are p_o (body)
  MassMatrix(q, mass_body_);
  const Eigen::Map<const VecX> nu(v, 6 + n_);
  nu_.noalias() = mass_body_ * nu;
  const Mat3 R = BodyQuat(q).toRotationMatrix();
  const Vec3 L = nu_.head<3>();
  Vec6 h;
  h.head<3>() = L;
  h.tail<3>() = Vec3(q[0], q[1], q[2]).cross(L) + R * nu_.segment<3>(3);
  return h;
}

void FlexibleBody::BodyFramePose(const double* q, Vec3& p_WB, Mat3& R_WB) const {
  R_WB = BodyQuat(q).toRotationMatrix();
  p_WB = Vec3(q[0], q[1], q[2]);
}

double FlexibleBody::StrainEnergy(const double* q) const {
  const Eigen::Map<const VecX> w(q + 7, n_);
  return 0.5 * w.dot(data_.reduced->stiffness * w);
}

void FlexibleBody::CheckNode(int node) const {
  if (node < 0 || node >= static_cast<int>(data_.reduced->mesh.nodes.size()))
    throw InputError("node index " + std::to_string(node) + " out of range",
                     {"", 0, "flexible body '" + name() + "'"});
}

Vec3 FlexibleBody::NodeDisplacement(const double* q, int node) const {
  CheckNode(node);
  return Ht(node) * Eigen::Map<const VecX>(q + 7, n_);
}

Vec3 FlexibleBody::NodePosition(const double* q, int node) const {
  CheckNode(node);
  Vec3 u = data_.reduced->mesh.nodes[node].x;
  u.noalias() += Ht(node) * Eigen::Map<const VecX>(q + 7, n_);
  return Vec3(q[0], q[1], q[2]) + BodyQuat(q).toRotationMatrix() * u;
}

Vec3 FlexibleBody::NodeVelocity(const double* q, const double* v, int node) const {
  CheckNode(node);
  Vec3 u = data_.reduced->mesh.nodes[node].x;
  u.noalias() += Ht(node) * Eigen::Map<const VecX>(q + 7, n_);
  Vec3 ud = Vec3(v[3], v[4], v[5]).cross(u);
  ud.noalias() += Ht(node) * Eigen::Map<const VecX>(v + 6, n_);
  return Vec3(v[0], v[1], v[2]) + BodyQuat(q).toRotationMatrix() * ud;
}

}  // namespace flexmb
