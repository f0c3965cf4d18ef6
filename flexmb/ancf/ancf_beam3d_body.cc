#include "flexmb/ancf/ancf_beam3d_body.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"

namespace flexmb::ancf {
namespace {

using Beam3dElVec = AncfBeam3d::Vec;
using Beam3dElMat = AncfBeam3d::Mat;

// (I - t t^T) / |a| = dt/da
Mat3 Beam3dTangentDerivative(const Vec3& a) {
  const double la = a.norm();
  const Vec3 t = a / la;
  return (Mat3::Identity() - t * t.transpose()) / la;
}

}  // namespace

AncfBeam3dBody::AncfBeam3dBody(std::string name, const AncfBeam3dData& data)
    : Body(std::move(name)), data_(data), n_el_(data.elements) {
  const ErrorContext ctx{"", 0, "body '" + this->name() + "'"};
  if (!(data_.length > 0.0) || !std::isfinite(data_.length))
    throw InputError("ANCF beam length must be positive, got " + std::to_string(data_.length), ctx);
  if (n_el_ <= 0)
    throw InputError("ANCF beam element count must be positive, got " + std::to_string(n_el_), ctx);
  if (!(data_.radius >= 0.0) || !std::isfinite(data_.radius))
    throw InputError("ANCF beam radius must not be negative (0: straight)", ctx);
  if (data_.radius > 0.0 && !(data_.length / data_.radius < std::numbers::pi))
    throw InputError("ANCF beam arc must turn by less than 180 degrees (length / radius < pi)", ctx);
  if (!data_.direction_W.allFinite() || !(data_.direction_W.norm() > 0.0))
    throw InputError("ANCF beam direction must be a non-zero vector", ctx);
  if (!data_.normal_W.allFinite() || !data_.load_per_length_W.allFinite() || !data_.start_W.allFinite())
    throw InputError("ANCF beam start, normal and load must be finite", ctx);
  const Vec3 t0 = data_.direction_W.normalized();
  Vec3 n = data_.normal_W;
  if (n.norm() == 0.0) n = std::abs(t0.z()) < 1.0 - 1e-6 ? Vec3::UnitZ() : Vec3::UnitX();
  const Vec3 z = n - t0 * t0.dot(n);
  if (!(z.norm() > 1e-6 * n.norm())) throw InputError("ANCF beam normal must not be parallel to its direction", ctx);
  R_W0_.col(0) = t0;
  R_W0_.col(2) = z.normalized();
  R_W0_.col(1) = R_W0_.col(2).cross(t0);
  // reference shape: straight or an arc turning about z0
  const double h = data_.length / n_el_;
  q0_.setZero(nq());
  for (int k = 0; k <= n_el_; ++k) {
    const double s = k * h;
    Vec3 r = data_.start_W + s * t0, a = t0;
    if (data_.radius > 0.0) {
      const double R = data_.radius, th = s / R;
      r = data_.start_W + R * std::sin(th) * t0 + R * (1.0 - std::cos(th)) * R_W0_.col(1);
      a = std::cos(th) * t0 + std::sin(th) * R_W0_.col(1);
    }
    q0_.segment<3>(7 * k) = r;
    q0_.segment<3>(7 * k + 3) = a;
  }
  elements_.reserve(n_el_);
  for (int i = 0; i < n_el_; ++i) {
    try {
      elements_.emplace_back(h, data_.section, R_W0_, data_.order);
    } catch (const InputError& e) {
      throw InputError(e.message(), ctx);
    }
    elements_.back().SetReference(q0_.segment<14>(7 * i));
  }
  mass_.setZero(nv(), nv());
  for (int i = 0; i < n_el_; ++i) mass_.block<14, 14>(7 * i, 7 * i) += elements_[i].MassMatrix();
}

void AncfBeam3dBody::InitialCoordinates(double* q, double* v) const {
  for (int j = 0; j < nq(); ++j) {
    q[j] = q0_(j);
    v[j] = 0.0;
  }
}

void AncfBeam3dBody::Retract(const double* q, const double* dx, double* q_out) const {
  for (int j = 0; j < nq(); ++j) q_out[j] = q[j] + dx[j];
}

void AncfBeam3dBody::MassMatrix(const double*, MatX& M) const { M = mass_; }

void AncfBeam3dBody::AddForces(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q,
                               Eigen::Ref<MatX> dQdq, Eigen::Ref<MatX> dQdv) const {
  const Beam3dSection& sec = data_.section;
  const Vec3 f = sec.rho * sec.A * g_W + data_.load_per_length_W;
  for (int i = 0; i < n_el_; ++i) {
    const Eigen::Map<const Beam3dElVec> e(q + 7 * i), edot(v + 7 * i);
    Beam3dElVec Qe = elements_[i].DistributedLoad(f);
    Beam3dElMat K = Beam3dElMat::Zero(), C = Beam3dElMat::Zero();
    elements_[i].AddInternalForces(e, edot, Qe, K, C);
    Q.segment<14>(7 * i) += Qe;
    dQdq.block<14, 14>(7 * i, 7 * i) += K;
    dQdv.block<14, 14>(7 * i, 7 * i) += C;
  }
}

bool AncfBeam3dBody::BlockPattern(std::vector<std::pair<int, int>>& entries) const {
  for (int e = 0; e < n_el_; ++e)
    for (int j = 0; j < 14; ++j)
      for (int i = 0; i < 14; ++i) entries.emplace_back(7 * e + i, 7 * e + j);
  return true;
}

int AncfBeam3dBody::NodeOf(const Marker& m) const {
  if (m.node < 0 || m.node > n_el_)
    throw InputError("marker on node " + std::to_string(m.node) + ", but the beam has nodes 0.." +
                         std::to_string(n_el_),
                     {"", 0, "marker '" + m.name + "'"});
  return m.node;
}

Mat3 AncfBeam3dBody::NodeFrame(const double* q, int k) const {
  const Eigen::Map<const Vec3> a(q + 7 * k + 3);
  const Mat3 D = AncfBeam3d::MinimalFrame(R_W0_, a);
  const double c = std::cos(q[7 * k + 6]), s = std::sin(q[7 * k + 6]);
  Mat3 F;
  F.col(0) = D.col(0);
  F.col(1) = c * D.col(1) + s * D.col(2);
  F.col(2) = c * D.col(2) - s * D.col(1);
  return F;
}

Mat3 AncfBeam3dBody::MarkerFrame(const double* q, const Marker& m) const {
  try {
    return NodeFrame(q, NodeOf(m));
  } catch (const NumericalError& e) {
    throw NumericalError(e.message() + " at marker '" + m.name + "'", {"", 0, "body '" + name() + "'"});
  }
}

void AncfBeam3dBody::EvaluateMarker(const double* q, const double* v, const Marker& m, MarkerState& out) const {
  const int k = NodeOf(m);
  const Eigen::Map<const Vec3> r(q + 7 * k), a(q + 7 * k + 3), rd(v + 7 * k), ad(v + 7 * k + 3);
  const double phid = v[7 * k + 6];
  const Mat3 R_WN = MarkerFrame(q, m);
  const Vec3 t = R_WN.col(0);
  const Mat3 G = AncfBeam3d::FrameRate(R_W0_.col(0), a);
  const Vec3 s = R_WN * m.p_BM;
  const Vec3 w = G * ad + phid * t;
  out.p_WM = r + s;
  out.R_WM = R_WN * m.R_BM;
  out.v_WM = rd + w.cross(s);
  out.w_WM = w;
  out.J.setZero(6, nv());
  out.J.block<3, 3>(0, 7 * k).setIdentity();
  out.J.block<3, 3>(0, 7 * k + 3) = -Skew(s) * G;
  out.J.block<3, 1>(0, 7 * k + 6) = t.cross(s);
  out.J.block<3, 3>(3, 7 * k + 3) = G;
  out.J.block<3, 1>(3, 7 * k + 6) = t;
  out.v_offset = v_offset;
  out.nv = nv();
}

Vec6 AncfBeam3dBody::MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const {
  const int k = NodeOf(m);
  const Eigen::Map<const Vec3> a(q + 7 * k + 3), ad(v + 7 * k + 3);
  const double phid = v[7 * k + 6];
  const Mat3 R_WN = MarkerFrame(q, m);
  const Vec3 t0 = R_W0_.col(0);
  const Vec3 s = R_WN * m.p_BM;
  const Vec3 w = AncfBeam3d::FrameRate(t0, a) * ad + phid * R_WN.col(0);
  const Vec3 alpha = AncfBeam3d::FrameRateDerivative(t0, a, ad) * ad + phid * (Beam3dTangentDerivative(a) * ad);
  Vec6 b;
  b.head<3>() = alpha.cross(s) + w.cross(w.cross(s));
  b.tail<3>() = alpha;
  return b;
}

void AncfBeam3dBody::AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                                            Eigen::Ref<MatX> dQdq) const {
  // Q_slope = G^T y, Q_twist = t . y with y = m + s x f; s turns with the
  // frame: ds = (G da + t dphi) x s
  const int k = NodeOf(m);
  const Eigen::Map<const Vec3> a(q + 7 * k + 3);
  const Mat3 R_WN = MarkerFrame(q, m);
  const Vec3 t0 = R_W0_.col(0), t = R_WN.col(0);
  const Vec3 s = R_WN * m.p_BM;
  const Mat3 G = AncfBeam3d::FrameRate(t0, a);
  const Vec3 f = wrench_W.head<3>();
  const Vec3 y = wrench_W.tail<3>() + s.cross(f);
  const Mat3 FS = Skew(f) * Skew(s);
  const int ia = 7 * k + 3, ip = 7 * k + 6;
  dQdq.block<3, 3>(ia, ia) += AncfBeam3d::FrameRateTransposeDerivative(t0, a, y) + G.transpose() * FS * G;
  dQdq.block<3, 1>(ia, ip) += G.transpose() * FS * t;
  dQdq.block<1, 3>(ip, ia) += y.transpose() * Beam3dTangentDerivative(a) + t.transpose() * FS * G;
  dQdq(ip, ip) += t.dot(FS * t);
}

void AncfBeam3dBody::MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                                        Eigen::Ref<MatX> out) const {
  const int k = NodeOf(m);
  const Eigen::Map<const Vec3> a(q + 7 * k + 3), ad(v + 7 * k + 3);
  const double phid = v[7 * k + 6];
  const Mat3 R_WN = MarkerFrame(q, m);
  const Vec3 t0 = R_W0_.col(0), t = R_WN.col(0);
  const Vec3 s = R_WN * m.p_BM;
  const Mat3 G = AncfBeam3d::FrameRate(t0, a);
  const Mat3 Hd = AncfBeam3d::FrameRateDerivative(t0, a, ad) + phid * Beam3dTangentDerivative(a);
  const Vec3 w = G * ad + phid * t;
  out.setZero();
  out.block<3, 3>(0, 7 * k + 3) = -Skew(s) * Hd - Skew(w) * Skew(s) * G;
  out.block<3, 1>(0, 7 * k + 6) = -Skew(w) * Skew(s) * t;
  out.block<3, 3>(3, 7 * k + 3) = Hd;
}

double AncfBeam3dBody::KineticEnergy(const double*, const double* v) const {
  double T = 0.0;
  for (int i = 0; i < n_el_; ++i) {
    const Eigen::Map<const Beam3dElVec> ve(v + 7 * i);
    T += 0.5 * ve.dot(elements_[i].MassMatrix() * ve);
  }
  return T;
}

double AncfBeam3dBody::GravityPotential(const double* q, const Vec3& g_W) const {
  const Beam3dSection& sec = data_.section;
  double V = 0.0;
  for (int i = 0; i < n_el_; ++i)
    V -= Eigen::Map<const Beam3dElVec>(q + 7 * i).dot(elements_[i].DistributedLoad(sec.rho * sec.A * g_W));
  return V;
}

double AncfBeam3dBody::ElasticEnergy(const double* q) const {
  double W = 0.0;
  for (int i = 0; i < n_el_; ++i) W += elements_[i].StrainEnergy(Eigen::Map<const Beam3dElVec>(q + 7 * i));
  return W;
}

Vec6 AncfBeam3dBody::Momentum(const double* q, const double* v) const {
  // translational mass m_ab (x) I3 over the vector slots r0, r'0, r1, r'1
  constexpr int off[4] = {0, 3, 7, 10};
  Vec3 p = Vec3::Zero(), L = Vec3::Zero();
  for (int i = 0; i < n_el_; ++i) AddAncfElementMomentum(elements_[i].MassMatrix(), q + 7 * i, v + 7 * i, off, p, L);
  Vec6 out;
  out << p, L;
  return out;
}

void AncfBeam3dBody::BodyFramePose(const double*, Vec3& p_WB, Mat3& R_WB) const {
  p_WB = data_.start_W;
  R_WB = R_W0_;
}

Vec3 AncfBeam3dBody::PositionAt(const double* q, double s) const {
  int i = 0;
  double xi = 0.0;
  LocateOnAncfLine(s, data_.length / n_el_, n_el_, i, xi);
  return elements_[i].Position(Eigen::Map<const Beam3dElVec>(q + 7 * i), xi);
}

}  // namespace flexmb::ancf
