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

// (I - t t^T) / |a| = dt/da
Mat3 Beam3dTangentDerivative(const Vec3& a) {
  const double la = a.norm();
  const Vec3 t = a / la;
  return (Mat3::Identity() - t * t.transpose()) / la;
}

}  // namespace

AncfBeam3dBody::AncfBeam3dBody(std::string name, const AncfBeam3dData& data)
    : Base(std::move(name), data.length, data.elements), data_(data) {
  const ErrorContext ctx = BodyContext();
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
  if (!data_.element_sections.empty() && static_cast<int>(data_.element_sections.size()) != n_el_)
    throw InputError("ANCF beam has " + std::to_string(data_.element_sections.size()) + " element sections for " +
                         std::to_string(n_el_) + " elements (give one per element)",
                     ctx);
  elements_.reserve(n_el_);
  for (int i = 0; i < n_el_; ++i) {
    const Beam3dSection& sec = data_.element_sections.empty() ? data_.section : data_.element_sections[i];
    NamingBody([&] { elements_.emplace_back(h, sec, R_W0_, data_.order); });
    elements_.back().SetReference(q0_.segment<14>(7 * i));
  }
  AssembleMass();
}

void AncfBeam3dBody::InitialCoordinates(double* q, double* v) const {
  for (int j = 0; j < nq(); ++j) {
    q[j] = q0_(j);
    v[j] = 0.0;
  }
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
  const Eigen::Map<const Vec3> a(q + 7 * k + 3), ad(v + 7 * k + 3);
  const double phid = v[7 * k + 6];
  const Mat3 R_WN = MarkerFrame(q, m);
  const Vec3 t = R_WN.col(0);
  const Mat3 G = AncfBeam3d::FrameRate(R_W0_.col(0), a);
  // the twist rate turns the frame about the tangent t
  const Vec3 s = FillNodeMarker(q, v, k, R_WN, G, G * ad + phid * t, m, out);
  out.J.block<3, 1>(0, 7 * k + 6) = t.cross(s);
  out.J.block<3, 1>(3, 7 * k + 6) = t;
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
  return OffsetMarkerBias(alpha, w, s);
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

Vec6 AncfBeam3dBody::Momentum(const double* q, const double* v) const {
  // translational mass m_ab (x) I3 over the vector slots r0, r'0, r1, r'1
  constexpr int off[4] = {0, 3, 7, 10};
  return CentreLineMomentum(q, v, off);
}

}  // namespace flexmb::ancf
