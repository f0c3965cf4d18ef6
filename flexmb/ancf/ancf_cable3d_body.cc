#include "flexmb/ancf/ancf_cable3d_body.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"

namespace flexmb::ancf {
namespace {

// value and directional derivative (forward-mode dual numbers) of a scalar
// and of a 3-vector: the exact derivatives of the node-frame rate
struct Ds {
  double v, d;
};
struct Dv {
  Vec3 v, d;
};

Ds Dot(const Dv& a, const Dv& b) { return {a.v.dot(b.v), a.d.dot(b.v) + a.v.dot(b.d)}; }
Dv Cross(const Dv& a, const Dv& b) { return {a.v.cross(b.v), a.d.cross(b.v) + a.v.cross(b.d)}; }
Dv Scale(const Ds& s, const Dv& a) { return {s.v * a.v, s.d * a.v + s.v * a.d}; }
Dv Sub(const Dv& a, const Dv& b) { return {a.v - b.v, a.d - b.d}; }
Dv Add(const Dv& a, const Dv& b) { return {a.v + b.v, a.d + b.d}; }

// angular velocity of Rmin(t0 -> a/|a|) for the slope rate ad:
// w = 2 (w_p cd - wd_p c + c x cd) / |p|^2 with p = (1 + t0.t, t0 x t)
Dv Rate(const Vec3& t0, const Dv& a, const Dv& ad) {
  const Dv T0{t0, Vec3::Zero()};
  const Ds aa = Dot(a, a);
  const double la = std::sqrt(aa.v);
  const Ds inv{1.0 / la, -0.5 * aa.d / (la * aa.v)};
  const Dv t = Scale(inv, a);
  const Dv td = Scale(inv, Sub(ad, Scale(Dot(t, ad), t)));
  const Ds w{1.0 + Dot(T0, t).v, Dot(T0, t).d};
  const Dv c = Cross(T0, t);
  const Ds wd = Dot(T0, td);
  const Dv cd = Cross(T0, td);
  const Ds p2{w.v * w.v + c.v.squaredNorm(), 2.0 * w.v * w.d + 2.0 * c.v.dot(c.d)};
  const Ds f{2.0 / p2.v, -2.0 * p2.d / (p2.v * p2.v)};
  return Scale(f, Add(Sub(Scale(w, cd), Scale(wd, c)), Cross(c, cd)));
}

}  // namespace

AncfCable3dBody::AncfCable3dBody(std::string name, const AncfCable3dData& data)
    : Base(std::move(name), data.length, data.elements),
      data_(data),
      element_(NamingBody([&] { return AncfCable3d(data.length / data.elements, data.section, data.order); })) {
  const ErrorContext ctx = BodyContext();
  if (!data_.direction_W.allFinite() || !(data_.direction_W.norm() > 0.0))
    throw InputError("ANCF cable direction must be a non-zero vector", ctx);
  if (!data_.normal_W.allFinite() || !data_.load_per_length_W.allFinite() ||
      !data_.start_W.allFinite() || !data_.angular_velocity_W.allFinite())
    throw InputError("ANCF cable start, normal, load and angular velocity must be finite", ctx);
  t0_ = data_.direction_W.normalized();
  Vec3 n = data_.normal_W;
  if (n.norm() == 0.0) n = std::abs(t0_.z()) < 1.0 - 1e-6 ? Vec3::UnitZ() : Vec3::UnitX();
  const Vec3 z = n - t0_ * t0_.dot(n);
  if (!(z.norm() > 1e-6 * n.norm()))
    throw InputError("ANCF cable normal must not be parallel to its direction", ctx);
  R_W0_.col(0) = t0_;
  R_W0_.col(2) = z.normalized();
  R_W0_.col(1) = R_W0_.col(2).cross(t0_);
  AssembleMass();
}

void AncfCable3dBody::InitialCoordinates(double* q, double* v) const {
  const double h = element_.length();
  const Vec3& w = data_.angular_velocity_W;
  for (int i = 0; i <= n_el_; ++i) {
    const Vec3 r = data_.start_W + (i * h) * t0_;
    Eigen::Map<Vec3>(q + 6 * i) = r;
    Eigen::Map<Vec3>(q + 6 * i + 3) = t0_;
    Eigen::Map<Vec3>(v + 6 * i) = w.cross(r - data_.start_W);
    Eigen::Map<Vec3>(v + 6 * i + 3) = w.cross(t0_);
  }
}

Mat3 AncfCable3dBody::NodeFrame(const Vec3& a, const std::string& marker) const {
  const double la = a.norm();
  const Vec3 t = a / la;
  const double w = 1.0 + t0_.dot(t);
  if (!(la > 0.0) || !(w > 1e-8))
    throw NumericalError("the slope of the ANCF cable at marker '" + marker + "'" +
                         " vanished or turned back against its reference direction (the node "
                         "frame rule is singular there)",
                         {"", 0, "body '" + name() + "'"});
  const Vec3 c = t0_.cross(t);
  const Eigen::Quaterniond p(w, c.x(), c.y(), c.z());
  return p.normalized().toRotationMatrix() * R_W0_;
}

Mat3 AncfCable3dBody::RateMatrix(const Vec3& a, const Marker& m) const {
  NodeFrame(a, m.name);
  Mat3 G;
  for (int j = 0; j < 3; ++j) G.col(j) = Rate(t0_, {a, Vec3::Zero()}, {Vec3::Unit(j), Vec3::Zero()}).v;
  return G;
}

Mat3 AncfCable3dBody::RateDerivative(const Vec3& a, const Vec3& u) const {
  Mat3 H;
  for (int j = 0; j < 3; ++j) H.col(j) = Rate(t0_, {a, Vec3::Unit(j)}, {u, Vec3::Zero()}).d;
  return H;
}

Mat3 AncfCable3dBody::RateTransposeDerivative(const Vec3& a, const Vec3& y) const {
  Mat3 W;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) W(i, j) = y.dot(Rate(t0_, {a, Vec3::Unit(j)}, {Vec3::Unit(i), Vec3::Zero()}).d);
  return W;
}

void AncfCable3dBody::EvaluateMarker(const double* q, const double* v, const Marker& m,
                                     MarkerState& out) const {
  const int k = NodeOf(m);
  const Eigen::Map<const Vec3> a(q + 6 * k + 3), ad(v + 6 * k + 3);
  const Mat3 R_WN = NodeFrame(a, m.name);
  const Mat3 G = RateMatrix(a, m);
  FillNodeMarker(q, v, k, R_WN, G, G * ad, m, out);
}

Vec6 AncfCable3dBody::MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const {
  const int k = NodeOf(m);
  const Eigen::Map<const Vec3> a(q + 6 * k + 3), ad(v + 6 * k + 3);
  const Vec3 s = NodeFrame(a, m.name) * m.p_BM;
  const Vec3 w = RateMatrix(a, m) * ad;
  const Vec3 alpha = RateDerivative(a, ad) * ad;
  return OffsetMarkerBias(alpha, w, s);
}

void AncfCable3dBody::AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                                             Eigen::Ref<MatX> dQdq) const {
  // Q_slope = G^T (m + s x f); s turns with the node frame: ds = (G da) x s
  const int k = NodeOf(m);
  const Eigen::Map<const Vec3> a(q + 6 * k + 3);
  const Vec3 s = NodeFrame(a, m.name) * m.p_BM;
  const Mat3 G = RateMatrix(a, m);
  const Vec3 f = wrench_W.head<3>(), mom = wrench_W.tail<3>();
  dQdq.block<3, 3>(6 * k + 3, 6 * k + 3) +=
      RateTransposeDerivative(a, mom + s.cross(f)) + G.transpose() * Skew(f) * Skew(s) * G;
}

void AncfCable3dBody::MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                                         Eigen::Ref<MatX> out) const {
  const int k = NodeOf(m);
  const Eigen::Map<const Vec3> a(q + 6 * k + 3), ad(v + 6 * k + 3);
  const Vec3 s = NodeFrame(a, m.name) * m.p_BM;
  const Mat3 G = RateMatrix(a, m);
  const Mat3 H = RateDerivative(a, ad);
  const Vec3 w = G * ad;
  out.setZero();
  out.block<3, 3>(0, 6 * k + 3) = -Skew(s) * H - Skew(w) * Skew(s) * G;
  out.block<3, 3>(3, 6 * k + 3) = H;
}

Vec6 AncfCable3dBody::Momentum(const double* q, const double* v) const {
  constexpr int off[4] = {0, 3, 6, 9};
  return CentreLineMomentum(q, v, off);
}

}  // namespace flexmb::ancf
