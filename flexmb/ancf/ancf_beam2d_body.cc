#include "flexmb/ancf/ancf_beam2d_body.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "flexmb/common/error.h"

namespace flexmb::ancf {
namespace {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;
using BeamElVec = AncfBeam2d::Vec;

// rotation of the node frame in plane axes: x along the slope a
Mat3 PlaneRotation(const Vec2& a) {
  const Vec2 t = a.normalized();
  Mat3 R = Mat3::Identity();
  R(0, 0) = t.x(), R(0, 1) = -t.y();
  R(1, 0) = t.y(), R(1, 1) = t.x();
  return R;
}

}  // namespace

AncfBeam2dBody::AncfBeam2dBody(std::string name, const AncfBeam2dData& data)
    : Base(std::move(name), data.length, data.elements),
      data_(data),
      element_(NamingBody(
          [&] { return AncfBeam2d(data.length / data.elements, data.section, data.curvature0, data.order); })) {
  const ErrorContext ctx = BodyContext();
  const Vec3 n = data_.normal_W.normalized();
  const Vec3 d = data_.direction_W - n * n.dot(data_.direction_W);
  if (!(data_.normal_W.norm() > 0.0) || !(d.norm() > 1e-9 * data_.direction_W.norm()))
    throw InputError("ANCF beam direction must be non-zero and not parallel to the plane normal", ctx);
  R_WP_.col(0) = d.normalized();
  R_WP_.col(2) = n;
  R_WP_.col(1) = n.cross(R_WP_.col(0));
  if (!data_.load_per_length_W.allFinite()) throw InputError("ANCF beam load is not finite", ctx);
  AssembleMass();
}

void AncfBeam2dBody::InitialCoordinates(double* q, double* v) const {
  const double h = element_.length();
  const double k = data_.curvature0;
  for (int i = 0; i <= n_el_; ++i) {
    const double s = i * h;
    if (k == 0.0) {
      q[4 * i] = s, q[4 * i + 1] = 0.0, q[4 * i + 2] = 1.0, q[4 * i + 3] = 0.0;
    } else {
      q[4 * i] = std::sin(k * s) / k, q[4 * i + 1] = (1.0 - std::cos(k * s)) / k;
      q[4 * i + 2] = std::cos(k * s), q[4 * i + 3] = std::sin(k * s);
    }
  }
  for (int j = 0; j < nv(); ++j) v[j] = 0.0;
}

void AncfBeam2dBody::EvaluateMarker(const double* q, const double* v, const Marker& m,
                                    MarkerState& out) const {
  const int k = NodeOf(m);
  const Vec2 r(q[4 * k], q[4 * k + 1]), a(q[4 * k + 2], q[4 * k + 3]);
  const Vec2 rd(v[4 * k], v[4 * k + 1]), ad(v[4 * k + 2], v[4 * k + 3]);
  const Vec3 n = R_WP_.col(2);
  const Mat3 R_WN = R_WP_ * PlaneRotation(a);
  const Vec3 s = R_WN * m.p_BM;
  const Vec3 ns = n.cross(s);
  const Vec2 h = Vec2(-a.y(), a.x()) / a.squaredNorm();
  const double thetad = h.dot(ad);
  out.p_WM = data_.start_W + R_WP_.leftCols<2>() * r + s;
  out.R_WM = R_WN * m.R_BM;
  out.v_WM = R_WP_.leftCols<2>() * rd + thetad * ns;
  out.w_WM = thetad * n;
  out.J.setZero(6, nv());
  out.J.block<3, 2>(0, 4 * k) = R_WP_.leftCols<2>();
  out.J.block<3, 2>(0, 4 * k + 2) = ns * h.transpose();
  out.J.block<3, 2>(3, 4 * k + 2) = n * h.transpose();
  out.v_offset = v_offset;
  out.nv = nv();
}

Vec6 AncfBeam2dBody::MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const {
  const int k = NodeOf(m);
  const Vec2 a(q[4 * k + 2], q[4 * k + 3]), ad(v[4 * k + 2], v[4 * k + 3]);
  const Vec3 n = R_WP_.col(2);
  const Vec3 s = R_WP_ * PlaneRotation(a) * m.p_BM;
  const double g = a.squaredNorm();
  const double thetad = (a.x() * ad.y() - a.y() * ad.x()) / g;
  // theta'' = h . a'' + hdot . a', hdot . a' = -2 thetad (a . a') / g
  const double beta = -2.0 * thetad * a.dot(ad) / g;
  Vec6 b;
  b.head<3>() = beta * n.cross(s) + thetad * thetad * n.cross(n.cross(s));
  b.tail<3>() = beta * n;
  return b;
}

void AncfBeam2dBody::AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                                            Eigen::Ref<MatX> dQdq) const {
  // Q_slope = h (f . (n x s) + m . n); h = J2 a / g; s turns with theta
  const int k = NodeOf(m);
  const Vec2 a(q[4 * k + 2], q[4 * k + 3]);
  const Vec3 n = R_WP_.col(2);
  const Vec3 s = R_WP_ * PlaneRotation(a) * m.p_BM;
  const Vec3 f = wrench_W.head<3>(), mom = wrench_W.tail<3>();
  const double g = a.squaredNorm();
  const Vec2 h = Vec2(-a.y(), a.x()) / g;
  Mat2 J2;
  J2 << 0.0, -1.0, 1.0, 0.0;
  const Mat2 H = J2 / g - 2.0 * h * a.transpose() / g;
  const double c1 = f.dot(n.cross(s)) + mom.dot(n);
  const double c2 = f.dot(n.cross(n.cross(s)));
  dQdq.block<2, 2>(4 * k + 2, 4 * k + 2) += c1 * H + c2 * h * h.transpose();
}

void AncfBeam2dBody::MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                                        Eigen::Ref<MatX> out) const {
  const int k = NodeOf(m);
  const Vec2 a(q[4 * k + 2], q[4 * k + 3]), ad(v[4 * k + 2], v[4 * k + 3]);
  const Vec3 n = R_WP_.col(2);
  const Vec3 s = R_WP_ * PlaneRotation(a) * m.p_BM;
  const double g = a.squaredNorm();
  const Vec2 h = Vec2(-a.y(), a.x()) / g;
  Mat2 J2;
  J2 << 0.0, -1.0, 1.0, 0.0;
  const Mat2 H = J2 / g - 2.0 * h * a.transpose() / g;
  const double thetad = h.dot(ad);
  const Eigen::RowVector2d dthetad = ad.transpose() * H;
  out.setZero();
  out.block<3, 2>(0, 4 * k + 2) = n.cross(s) * dthetad + thetad * n.cross(n.cross(s)) * h.transpose();
  out.block<3, 2>(3, 4 * k + 2) = n * dthetad;
}

Vec6 AncfBeam2dBody::Momentum(const double* q, const double* v) const {
  const BeamSection& sec = element_.section();
  const BeamElVec Sx = element_.DistributedLoad(sec.rho * sec.A * Vec2::UnitX());
  const BeamElVec Sy = element_.DistributedLoad(sec.rho * sec.A * Vec2::UnitY());
  Vec2 p = Vec2::Zero();
  double Lz = 0.0;
  for (int i = 0; i < n_el_; ++i) {
    const Eigen::Map<const BeamElVec> e(q + 4 * i), ve(v + 4 * i);
    p += Vec2(Sx.dot(ve), Sy.dot(ve));
    // int rho A (r x rdot) ds = e^T M w, w_a = (rdot_a,y, -rdot_a,x) per 2-vector
    BeamElVec w;
    for (int a = 0; a < 4; ++a) w(2 * a) = ve(2 * a + 1), w(2 * a + 1) = -ve(2 * a);
    Lz += e.dot(element_.MassMatrix() * w);
  }
  const Vec3 P = R_WP_.leftCols<2>() * p;
  Vec6 out;
  out.head<3>() = P;
  out.tail<3>() = data_.start_W.cross(P) + Lz * R_WP_.col(2);
  return out;
}

}  // namespace flexmb::ancf
