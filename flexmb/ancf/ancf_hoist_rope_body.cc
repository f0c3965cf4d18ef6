#include "flexmb/ancf/ancf_hoist_rope_body.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"

namespace flexmb::ancf {
namespace {

// Kelvin-Voigt strain term with a stiffness that depends on L (index 12 of
// the extended element coordinates y = (q_e, L)): energy 1/2 k s^2 and
// dissipation function 1/2 beta k sdot^2 with sdot = d1 . ydot. Subtracts
// the gradient from Q and the tangents from K (dQ/dy) and C (dQ/dydot).
template <class V, class M>
void AddVariableStiffnessTerm(double k, double dk, double ddk, double beta, double s, const V& d1, const M& d2,
                              const V& ydot, V& Q, M& K, M& C) {
  constexpr int kL = V::RowsAtCompileTime - 1;  // L: the last coordinate
  Q.noalias() -= (k * s) * d1;
  Q(kL) -= 0.5 * s * s * dk;
  K.noalias() -= k * (d1 * d1.transpose() + s * d2);
  K.col(kL) -= (s * dk) * d1;
  K.row(kL) -= (s * dk) * d1.transpose();
  K(kL, kL) -= 0.5 * s * s * ddk;
  if (beta > 0.0) {
    const double rate = d1.dot(ydot);
    Q.noalias() -= (beta * k * rate) * d1;
    C.noalias() -= (beta * k) * d1 * d1.transpose();
    K.noalias() -= (beta * k) * (rate * d2 + d1 * (d2 * ydot).transpose());
    K.col(kL) -= (beta * rate * dk) * d1;
  }
}

// The force of AddVariableStiffnessTerm without its tangents.
template <class V>
void AddVariableStiffnessForce(double k, double dk, double beta, double s, const V& d1, const V& ydot, V& Q) {
  Q.noalias() -= (k * s) * d1;
  Q(12) -= 0.5 * s * s * dk;
  if (beta > 0.0) Q.noalias() -= (beta * k * d1.dot(ydot)) * d1;
}

// The bending term of AddVariableStiffnessTerm (K, C null: the force only) for the three strains
// kappa = (a x b) / g, g = a . a, of a = A q_e, b = B q_e (A, B: the slope
// and curvature shape matrices, [s_i I] and [t_i I]), by the chain rule
// through (a, b): with J = d kappa / d(a, b) (3 x 6) and H_j = d2 kappa_j /
// d(a, b)2 (6 x 6), the 12 x 12 blocks are G^T X G with G = [A; B], formed
// block by block from the shape values instead of as products of 3 x 12
// matrices (the three strains' 13 x 13 terms cost 4 times as much).
template <class Shape, class V, class M>
void BendingTerm(double k, double dk, double ddk, double beta, const Shape& A, const Shape& B, const Vec3& a,
                 const Vec3& b, double g, const V& ydot, V& Q, M* Kp, M* Cp) {
  const Vec3 c = a.cross(b), kappa = c / g;
  const Mat3 Ja = -Skew(b) / g - (2.0 / (g * g)) * c * a.transpose(), Jb = Skew(a) / g;
  const Vec3 ad = A * ydot.template head<12>(), bd = B * ydot.template head<12>();
  const Vec3 kd = Ja * ad + Jb * bd;  // strain rates
  // the weights of the H_j: stiffness and damping
  const Vec3 w = k * kappa + (beta * k) * kd;
  if (!Kp) {
    const Vec3 fa = Ja.transpose() * w, fb = Jb.transpose() * w;
    for (int i = 0; i < 4; ++i) Q.template segment<3>(3 * i) -= A(0, 3 * i) * fa + B(0, 3 * i) * fb;
    Q(12) -= 0.5 * kappa.squaredNorm() * dk;
    return;
  }
  M& K = *Kp;
  M& C = *Cp;
  const double wc = w.dot(c);
  const Vec3 bw = b.cross(w), aw = a.cross(w);
  Mat3 Haa = -(2.0 / (g * g)) * (a * bw.transpose() + bw * a.transpose()) +
             (8.0 * wc / (g * g * g)) * a * a.transpose();
  Haa.diagonal().array() -= 2.0 * wc / (g * g);
  const Mat3 Hab = -Skew(w) / g + (2.0 / (g * g)) * a * aw.transpose();
  // damping: beta k sum_j J_j^T (H_j u)^T with u = (ad, bd)
  Mat3 Za, Zb;  // rows (H_j u)^T, split in the a and b parts
  for (int j = 0; j < 3; ++j) {
    const Vec3 wj = -Skew(b).row(j).transpose(), vj = Skew(a).row(j).transpose();
    Mat3 haa = -(2.0 / (g * g)) * (a * wj.transpose() + wj * a.transpose()) +
               (8.0 * c(j) / (g * g * g)) * a * a.transpose();
    haa.diagonal().array() -= 2.0 * c(j) / (g * g);
    const Mat3 hab = Skew(Vec3::Unit(j)).transpose() / g - (2.0 / (g * g)) * a * vj.transpose();
    Za.row(j) = (haa * ad + hab * bd).transpose();
    Zb.row(j) = (hab.transpose() * ad).transpose();
  }
  // 6 x 6 blocks of dQ/d(a, b) (negated below) and of dQ/d(a, b)dot
  const Mat3 Kaa = k * Ja.transpose() * Ja + Haa + beta * k * Ja.transpose() * Za;
  const Mat3 Kab = k * Ja.transpose() * Jb + Hab + beta * k * Ja.transpose() * Zb;
  const Mat3 Kba = k * Jb.transpose() * Ja + Hab.transpose() + beta * k * Jb.transpose() * Za;
  const Mat3 Kbb = k * Jb.transpose() * Jb + beta * k * Jb.transpose() * Zb;
  const Mat3 Caa = beta * k * Ja.transpose() * Ja, Cab = beta * k * Ja.transpose() * Jb,
             Cbb = beta * k * Jb.transpose() * Jb;
  // forces on (a, b), and the L column: k = k0 N / L
  const Vec3 fa = Ja.transpose() * w, fb = Jb.transpose() * w;
  const Vec3 ga = dk * Ja.transpose() * kappa, gb = dk * Jb.transpose() * kappa;
  const Vec3 ha = (beta * dk) * Ja.transpose() * kd, hb = (beta * dk) * Jb.transpose() * kd;
  for (int i = 0; i < 4; ++i) {
    const double si = A(0, 3 * i), ti = B(0, 3 * i);
    Q.template segment<3>(3 * i) -= si * fa + ti * fb;
    K.template block<3, 1>(3 * i, 12) -= si * (ga + ha) + ti * (gb + hb);
    K.template block<1, 3>(12, 3 * i) -= (si * ga + ti * gb).transpose();
    for (int m = 0; m < 4; ++m) {
      const double sm = A(0, 3 * m), tm = B(0, 3 * m);
      K.template block<3, 3>(3 * i, 3 * m) -= (si * sm) * Kaa + (si * tm) * Kab + (ti * sm) * Kba + (ti * tm) * Kbb;
      C.template block<3, 3>(3 * i, 3 * m) -=
          (si * sm) * Caa + (si * tm) * Cab + (ti * sm) * Cab.transpose() + (ti * tm) * Cbb;
    }
  }
  Q(12) -= 0.5 * kappa.squaredNorm() * dk;
  K(12, 12) -= 0.5 * kappa.squaredNorm() * ddk;
}

}  // namespace

AncfHoistRopeBody::AncfHoistRopeBody(std::string name, const HoistRopeData& data)
    : Body(std::move(name)), data_(data), n_el_(data.elements), nL_(6 * (data.elements + 1)) {
  const ErrorContext ctx{"", 0, "body '" + this->name() + "'"};
  const BeamSection& s = data_.section;
  auto positive = [&](double x, const char* what) {
    if (!(x > 0.0) || !std::isfinite(x))
      throw InputError(std::string("hoist rope ") + what + " must be positive, got " + std::to_string(x), ctx);
  };
  positive(data_.free_length, "free length");
  if (n_el_ <= 0) throw InputError("hoist rope element count must be positive, got " + std::to_string(n_el_), ctx);
  positive(s.E, "E");
  positive(s.A, "area");
  positive(s.I, "bending inertia");
  positive(s.rho, "density");
  if (data_.drum_in_body) positive(data_.drum_radius, "drum radius");
  if (!(data_.initial_length >= 0.0) || !std::isfinite(data_.initial_length))
    throw InputError("hoist rope initial length must be >= 0 (0: the free length), got " +
                         std::to_string(data_.initial_length),
                     ctx);
  if (!(data_.stored_length >= 0.0) || !(data_.drum_inertia >= 0.0) || !(s.damping >= 0.0))
    throw InputError("hoist rope stored length, drum inertia and damping must not be negative", ctx);
  if (data_.drum_in_body && !(data_.stored_length > 0.0) && !(data_.drum_inertia > 0.0))
    throw InputError("hoist rope needs rope stored on the drum or a drum inertia (else paying out a "
                     "straight rope moves no mass and the free length has no inertia)",
                     ctx);
  if (!data_.direction_W.allFinite() || !(data_.direction_W.norm() > 0.0) || !data_.start_W.allFinite() ||
      !data_.drum_W.allFinite() || !std::isfinite(data_.payout_speed))
    throw InputError("hoist rope start, drum and payout speed must be finite and the direction non-zero", ctx);
  rhoA_ = s.rho * s.A;
  L_total_ = data_.free_length + data_.stored_length;
  m_drum_ = data_.drum_in_body ? data_.drum_inertia / (data_.drum_radius * data_.drum_radius) : 0.0;
  rhoS_ = data_.drum_in_body ? rhoA_ : 0.0;
  const Vec3 t0 = data_.direction_W.normalized();
  const Vec3 n = std::abs(t0.z()) < 1.0 - 1e-6 ? Vec3::UnitZ() : Vec3::UnitX();
  R_W0_.col(0) = t0;
  R_W0_.col(2) = (n - t0 * t0.dot(n)).normalized();
  R_W0_.col(1) = R_W0_.col(2).cross(t0);

  const double *xs = nullptr, *ws = nullptr;
  GaussPoints01(5, xs, ws);  // exact: the integrands are polynomials of degree <= 8
  M0_.setZero(), Ca_.setZero(), Cb_.setZero(), Da_.setZero(), Db_.setZero(), Dc_.setZero();
  for (int g = 0; g < 5; ++g) {
    const Shape A = S0(xs[g]), B = S1(xs[g]);
    const double w = ws[g] * rhoA_, x = xs[g];
    M0_.noalias() += w * A.transpose() * A;
    Ca_.noalias() += w * A.transpose() * B;
    Cb_.noalias() += (w * x) * A.transpose() * B;
    Da_.noalias() += w * B.transpose() * B;
    Db_.noalias() += (w * x) * B.transpose() * B;
    Dc_.noalias() += (w * x * x) * B.transpose() * B;
  }
  for (VecX* t : {&t1_, &t2_, &t3_, &t4_, &t5_, &t6_}) t->setZero(nL_);
  // every integrand above is (s t^T) (x) I3: keep its 4 x 4 factor
  const auto factor = [](const Mat12& X) {
    Eigen::Matrix4d f;
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k) f(i, k) = X(3 * i, 3 * k);
    return f;
  };
  m0_ = factor(M0_), ca_ = factor(Ca_), cb_ = factor(Cb_), da_ = factor(Da_), db_ = factor(Db_), dc_ = factor(Dc_);
}

void AncfHoistRopeBody::InitialCoordinates(double* q, double* v) const {
  const double span = data_.initial_length > 0.0 ? data_.initial_length : data_.free_length;
  const double h = span / n_el_, hd = data_.payout_speed / n_el_;
  const Vec3 t0 = R_W0_.col(0);
  for (int k = 0; k <= n_el_; ++k) {
    Eigen::Map<Vec3>(q + 6 * k) = data_.start_W + (k * h) * t0;
    Eigen::Map<Vec3>(q + 6 * k + 3) = h * t0;
    Eigen::Map<Vec3>(v + 6 * k) = (k * hd) * t0;  // mesh points: the material moves through them
    Eigen::Map<Vec3>(v + 6 * k + 3) = hd * t0;
  }
  q[nL_] = data_.free_length;
  v[nL_] = data_.payout_speed;
}

void AncfHoistRopeBody::Retract(const double* q, const double* dx, double* q_out) const {
  for (int j = 0; j < nq(); ++j) q_out[j] = q[j] + dx[j];
}

template <class BlockOf>
void AncfHoistRopeBody::ApplyBanded(BlockOf&& block, const double* x, VecX& y) const {
  y.setZero(nL_);
  for (int e = 0; e < n_el_; ++e)
    y.segment<12>(6 * e).noalias() += block(e) * Eigen::Map<const Vec12>(x + 6 * e);
}

std::pair<double, double> AncfHoistRopeBody::RopeMasses(const double* q) const {
  return {rhoA_ * q[nL_], rhoS_ * (L_total_ - q[nL_])};
}

void AncfHoistRopeBody::MassMatrix(const double* q, MatX& M) const {
  const double L = q[nL_];
  const double N = n_el_;
  M.setZero(nv(), nv());
  for (int e = 0; e < n_el_; ++e) M.block<12, 12>(6 * e, 6 * e) += (L / N) * M0_;
  const auto Cb = [&](int e) -> Mat12 { return ((N - e) * Ca_ - Cb_) / N; };
  const auto Db = [&](int e) -> Mat12 { return ((N - e) * (N - e) * Da_ - 2.0 * (N - e) * Db_ + Dc_) / N; };
  ApplyBanded(Cb, q, t1_);
  ApplyBanded(Db, q, t2_);
  M.col(nL_).head(nL_) = t1_;
  M.row(nL_).head(nL_) = t1_.transpose();
  M(nL_, nL_) = Eigen::Map<const VecX>(q, nL_).dot(t2_) / L + rhoS_ * (L_total_ - L) + m_drum_;
}

void AncfHoistRopeBody::AddMassTangent(const double* q, const double* a, double scale, Eigen::Ref<MatX> K) const {
  const double L = q[nL_], aL = a[nL_];
  const double N = n_el_;
  const Eigen::Map<const VecX> qq(q, nL_), aq(a, nL_);
  t1_.setZero(nL_), t2_.setZero(nL_), t3_.setZero(nL_);
  for (int e = 0; e < n_el_; ++e) {
    const Mat12 Cb = ((N - e) * Ca_ - Cb_) / N;
    const Mat12 Db = ((N - e) * (N - e) * Da_ - 2.0 * (N - e) * Db_ + Dc_) / N;
    K.block<12, 12>(6 * e, 6 * e) += (scale * aL) * Cb;
    t1_.segment<12>(6 * e).noalias() += (M0_ / N) * aq.segment<12>(6 * e);
    t2_.segment<12>(6 * e).noalias() += Cb.transpose() * aq.segment<12>(6 * e);
    t3_.segment<12>(6 * e).noalias() += Db * qq.segment<12>(6 * e);
  }
  K.col(nL_).head(nL_) += scale * t1_;
  K.row(nL_).head(nL_) += scale * (t2_ + (2.0 * aL / L) * t3_).transpose();
  K(nL_, nL_) += scale * aL * (-qq.dot(t3_) / (L * L) - rhoS_);
}

void AncfHoistRopeBody::AddForces(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q,
                                  Eigen::Ref<MatX> dQdq, Eigen::Ref<MatX> dQdv) const {
  Forces(q, v, g_W, Q, &dQdq, &dQdv);
}

bool AncfHoistRopeBody::AddForceVector(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q) const {
  Forces(q, v, g_W, Q, nullptr, nullptr);
  return true;
}

void AncfHoistRopeBody::Forces(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q,
                               Eigen::Ref<MatX>* dQdq_p, Eigen::Ref<MatX>* dQdv_p) const {
  const bool tangents = dQdq_p != nullptr;
  const double L = q[nL_], Ld = v[nL_];
  if (!(L > 0.0) || !std::isfinite(L))
    throw NumericalError("the free length of the hoist rope reached " + std::to_string(L) +
                             " m: the winch hauled in the whole span",
                         {"", 0, "body '" + name() + "'"});
  if (L > L_total_)
    throw NumericalError("the winch paid out " + std::to_string(L) + " m, more than the rope's length " +
                             std::to_string(L_total_) + " m (the drum is empty)",
                         {"", 0, "body '" + name() + "'"});
  const double N = n_el_;
  const Eigen::Map<const VecX> qq(q, nL_), vq(v, nL_);
  for (VecX* t : {&t1_, &t2_, &t3_, &t4_, &t5_, &t6_}) t->setZero();
  const Vec3 gq[4] = {0.5 * g_W, g_W / 12.0, 0.5 * g_W, -g_W / 12.0};  // int S dxi, times g
  // (X (x) I3) x = vec(x_3x4 X^T): the element's 12 coordinates as 3 x 4
  using Mat34 = Eigen::Matrix<double, 3, 4>;
  const auto kron = [](const Eigen::Matrix4d& X, const double* x, double* y) {
    Eigen::Map<Mat34>(y) += Eigen::Map<const Mat34>(x) * X.transpose();
  };
  const Eigen::Matrix4d mb = m0_ / N;
  for (int e = 0; e < n_el_; ++e) {
    const Eigen::Matrix4d cb = ((N - e) * ca_ - cb_) / N;
    const Eigen::Matrix4d db = ((N - e) * (N - e) * da_ - 2.0 * (N - e) * db_ + dc_) / N;
    const auto qe = qq.segment<12>(6 * e);
    const auto ve = vq.segment<12>(6 * e);
    kron(mb, v + 6 * e, t1_.data() + 6 * e);
    kron(cb, v + 6 * e, t2_.data() + 6 * e);
    kron(cb.transpose(), v + 6 * e, t3_.data() + 6 * e);
    kron(db, q + 6 * e, t4_.data() + 6 * e);
    kron(db, v + 6 * e, t5_.data() + 6 * e);
    for (int a = 0; a < 4; ++a) t6_.segment<3>(6 * e + 3 * a) += (rhoA_ / N) * gq[a];
    // strain energy and damping of the element, extended coordinates (q_e, L)
    Vec13 y, yd, Qe = Vec13::Zero();
    y << qe, L;
    yd << ve, Ld;
    Mat13 K, C;
    if (tangents) K.setZero(), C.setZero();
    ElementStrain(e, y, yd, &Qe, tangents ? &K : nullptr, tangents ? &C : nullptr);
    Q.segment<12>(6 * e) += Qe.head<12>();
    Q(nL_) += Qe(12);
    if (!tangents) continue;
    Eigen::Ref<MatX>& dQdq = *dQdq_p;
    Eigen::Ref<MatX>& dQdv = *dQdv_p;
    const Eigen::Matrix4d dv = -Ld * (mb + cb - cb.transpose()), dq = (Ld * Ld / L) * db;
    for (int i = 0; i < 4; ++i)
      for (int m = 0; m < 4; ++m)
        for (int c = 0; c < 3; ++c) {
          dQdv(6 * e + 3 * i + c, 6 * e + 3 * m + c) += dv(i, m);
          dQdq(6 * e + 3 * i + c, 6 * e + 3 * m + c) += dq(i, m);
        }
    dQdq.block<12, 12>(6 * e, 6 * e) += K.topLeftCorner<12, 12>();
    dQdv.block<12, 12>(6 * e, 6 * e) += C.topLeftCorner<12, 12>();
    dQdq.block<12, 1>(6 * e, nL_) += K.topRightCorner<12, 1>();
    dQdv.block<12, 1>(6 * e, nL_) += C.topRightCorner<12, 1>();
    dQdq.block<1, 12>(nL_, 6 * e) += K.bottomLeftCorner<1, 12>();
    dQdv.block<1, 12>(nL_, 6 * e) += C.bottomLeftCorner<1, 12>();
    dQdq(nL_, nL_) += K(12, 12);
    dQdv(nL_, nL_) += C(12, 12);
  }
  const double qDq = qq.dot(t4_), qDqd = qq.dot(t5_), qdCqd = vq.dot(t2_), qdMqd = vq.dot(t1_);
  // Lagrange's velocity terms of T, gravity: V = -L t6 . q - rho A (L_total - L) g . p_drum
  Q.head(nL_) += -Ld * (t1_ + t2_ - t3_) + (Ld * Ld / L) * t4_ + L * t6_;
  Q(nL_) += -qdCqd + 0.5 * qdMqd - 2.0 * Ld * qDqd / L + 0.5 * Ld * Ld * qDq / (L * L) + 0.5 * rhoS_ * Ld * Ld +
            t6_.dot(qq) - rhoS_ * g_W.dot(data_.drum_W);
  // fed over the sheave: the rope enters at node 0 from that height (so that
  // at rest the lead's pull equals the axial force at the top of the span)
  const double rhoF = data_.drum_in_body ? 0.0 : rhoA_;
  Q(nL_) -= rhoF * g_W.dot(qq.head<3>());
  if (!tangents) return;
  Eigen::Ref<MatX>& dQdq = *dQdq_p;
  Eigen::Ref<MatX>& dQdv = *dQdv_p;
  dQdv.col(nL_).head(nL_) += -(t1_ + t2_ - t3_) + (2.0 * Ld / L) * t4_;
  dQdq.col(nL_).head(nL_) += (-Ld * Ld / (L * L)) * t4_;
  dQdq.row(nL_).head(nL_) += ((-2.0 * Ld / L) * t5_ + (Ld * Ld / (L * L)) * t4_).transpose();
  dQdq(nL_, nL_) += 2.0 * Ld * qDqd / (L * L) - Ld * Ld * qDq / (L * L * L);
  dQdv.row(nL_).head(nL_) += (t1_ - t2_ - t3_ - (2.0 * Ld / L) * t4_).transpose();
  dQdv(nL_, nL_) += -2.0 * qDqd / L + Ld * qDq / (L * L) + rhoS_ * Ld;
  dQdq.col(nL_).head(nL_) += t6_;
  dQdq.row(nL_).head(nL_) += t6_.transpose();
  dQdq.block<1, 3>(nL_, 0) -= rhoF * g_W.transpose();
}

double AncfHoistRopeBody::ElementStrain(int e, const Vec13& y, const Vec13& yd, Vec13* Q, Mat13* K,
                                        Mat13* C) const {
  const BeamSection& s = data_.section;
  const double L = y(12), N = n_el_;
  const Vec12 qe = y.head<12>();
  const double beta = s.damping;
  double W = 0.0;
  const double *xs = nullptr, *ws = nullptr;
  GaussPoints01(5, xs, ws);
  for (int g = 0; g < 5; ++g) {
    const Shape A = S1(xs[g]);
    const Vec3 a = A * qe;
    const double la = a.norm();
    if (!(la > 0.0))
      throw NumericalError("the hoist rope's slope vanished in element " + std::to_string(e) +
                               " (the element collapsed)",
                           {"", 0, "body '" + name() + "'"});
    const Vec3 ah = a / la;
    const double lam = la * N / L;
    const bool gl = s.axial_strain == AxialStrainMeasure::kGreenLagrange;
    const double eps = gl ? 0.5 * (lam * lam - 1.0) : lam - 1.0, e1 = gl ? lam : 1.0, e2 = gl ? 1.0 : 0.0;
    const double k = s.E * s.A * ws[g] * L / N, dk = s.E * s.A * ws[g] / N;
    W += 0.5 * k * eps * eps;
    if (!Q) continue;
    if (!K) {
      Vec13 dl;
      dl.head<12>() = (N / L) * A.transpose() * ah;
      dl(12) = -lam / L;
      AddVariableStiffnessForce(k, dk, beta, eps, Vec13(e1 * dl), yd, *Q);
      continue;
    }
    // the term in z = (a, L), which is linear in y = (q_e, L): the 13 x 13
    // tangents are G^T (4 x 4) G with G = [A 0; 0 1], A = [s_0 I ... s_3 I]
    using Vec4 = Eigen::Matrix<double, 4, 1>;
    using Mat4 = Eigen::Matrix<double, 4, 4>;
    Vec4 dlz, zd;
    dlz << (N / L) * ah, -lam / L;
    zd << A * yd.head<12>(), yd(12);
    Mat4 ddlz;
    ddlz.topLeftCorner<3, 3>() = (N / (L * la)) * (Mat3::Identity() - ah * ah.transpose());
    ddlz.topRightCorner<3, 1>() = (-N / (L * L)) * ah;
    ddlz.bottomLeftCorner<1, 3>() = ddlz.topRightCorner<3, 1>().transpose();
    ddlz(3, 3) = 2.0 * lam / (L * L);
    const Vec4 d1z = e1 * dlz;
    const Mat4 d2z = e2 * dlz * dlz.transpose() + e1 * ddlz;
    Vec4 Qz = Vec4::Zero();
    Mat4 Kz = Mat4::Zero(), Cz = Mat4::Zero();
    AddVariableStiffnessTerm(k, dk, 0.0, beta, eps, d1z, d2z, zd, Qz, Kz, Cz);
    for (int i = 0; i < 4; ++i) {
      const double si = A(0, 3 * i);
      Q->segment<3>(3 * i) += si * Qz.head<3>();
      for (int m = 0; m < 4; ++m) {
        const double sism = si * A(0, 3 * m);
        K->block<3, 3>(3 * i, 3 * m) += sism * Kz.topLeftCorner<3, 3>();
        C->block<3, 3>(3 * i, 3 * m) += sism * Cz.topLeftCorner<3, 3>();
      }
      K->block<3, 1>(3 * i, 12) += si * Kz.topRightCorner<3, 1>();
      K->block<1, 3>(12, 3 * i) += si * Kz.bottomLeftCorner<1, 3>();
      C->block<3, 1>(3 * i, 12) += si * Cz.topRightCorner<3, 1>();
      C->block<1, 3>(12, 3 * i) += si * Cz.bottomLeftCorner<1, 3>();
    }
    (*Q)(12) += Qz(3);
    (*K)(12, 12) += Kz(3, 3);
    (*C)(12, 12) += Cz(3, 3);
  }
  GaussPoints01(4, xs, ws);
  for (int g = 0; g < 4; ++g) {
    const Shape A = S1(xs[g]), B = S2(xs[g]);
    const Vec3 a = A * qe, b = B * qe, c = a.cross(b);
    const double gg = a.squaredNorm();
    const double k = s.E * s.I * ws[g] * N / L, dk = -k / L, ddk = 2.0 * k / (L * L);
    W += 0.5 * k * c.squaredNorm() / (gg * gg);
    if (!Q) continue;
    BendingTerm(k, dk, ddk, beta, A, B, a, b, gg, yd, *Q, K, C);
  }
  return W;
}

bool AncfHoistRopeBody::BlockPattern(std::vector<std::pair<int, int>>& entries) const {
  for (int e = 0; e < n_el_; ++e)
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i) entries.emplace_back(6 * e + i, 6 * e + j);
  for (int i = 0; i <= nL_; ++i) {
    entries.emplace_back(i, nL_);
    entries.emplace_back(nL_, i);
  }
  return true;
}

int AncfHoistRopeBody::NodeOf(const Marker& m) const {
  if (m.node < 0 || m.node > n_el_ + 1)
    throw InputError("marker on node " + std::to_string(m.node) + ", but the hoist rope has nodes 0.." +
                         std::to_string(n_el_) + " and the payout marker " + std::to_string(n_el_ + 1),
                     {"", 0, "marker '" + m.name + "'"});
  if (m.p_BM.squaredNorm() > 0.0)
    throw InputError("a marker on a hoist rope is a point on the centre line: a position offset is not "
                     "supported",
                     {"", 0, "marker '" + m.name + "'"});
  return m.node;
}

std::pair<int, int> AncfHoistRopeBody::MarkerColumns(const Marker& m) const {
  const int k = NodeOf(m);
  return k > n_el_ ? std::pair<int, int>{nL_, 1} : std::pair<int, int>{6 * k, 3};
}

void AncfHoistRopeBody::EvaluateMarker(const double* q, const double* v, const Marker& m, MarkerState& out) const {
  const int k = NodeOf(m);
  out.J.setZero(6, nv());
  out.R_WM = R_W0_ * m.R_BM;
  out.w_WM.setZero();
  if (k > n_el_) {
    out.p_WM = Vec3(q[nL_], 0.0, 0.0);
    out.v_WM = Vec3(v[nL_], 0.0, 0.0);
    out.J(0, nL_) = 1.0;
  } else {
    out.p_WM = Eigen::Map<const Vec3>(q + 6 * k);
    out.v_WM = Eigen::Map<const Vec3>(v + 6 * k);
    out.J.block<3, 3>(0, 6 * k).setIdentity();
  }
  out.v_offset = v_offset;
  out.nv = nv();
}

Vec6 AncfHoistRopeBody::MarkerAccelerationBias(const double*, const double*, const Marker& m) const {
  NodeOf(m);
  return Vec6::Zero();
}

void AncfHoistRopeBody::AddMarkerWrenchTangent(const double*, const Marker& m, const Vec6&,
                                               Eigen::Ref<MatX>) const {
  NodeOf(m);
}

void AncfHoistRopeBody::MarkerTwistTangent(const double*, const double*, const Marker& m,
                                           Eigen::Ref<MatX> out) const {
  NodeOf(m);
  out.setZero();
}

double AncfHoistRopeBody::KineticEnergy(const double* q, const double* v) const {
  MatX M;
  MassMatrix(q, M);
  const Eigen::Map<const VecX> vv(v, nv());
  return 0.5 * vv.dot(M * vv);
}

double AncfHoistRopeBody::GravityPotential(const double* q, const Vec3& g_W) const {
  const double L = q[nL_], N = n_el_;
  const Vec3 gq[4] = {0.5 * g_W, g_W / 12.0, 0.5 * g_W, -g_W / 12.0};
  // fed over the sheave: the span's weight relative to node 0, where its
  // rope enters (the potential of the applied forces while node 0 stays)
  double V = -rhoS_ * (L_total_ - L) * g_W.dot(data_.drum_W);
  if (!data_.drum_in_body) V += rhoA_ * L * g_W.dot(Eigen::Map<const Vec3>(q));
  for (int e = 0; e < n_el_; ++e)
    for (int a = 0; a < 4; ++a) V -= L * (rhoA_ / N) * gq[a].dot(Eigen::Map<const Vec3>(q + 6 * e + 3 * a));
  return V;
}

double AncfHoistRopeBody::ElasticEnergy(const double* q) const {
  double W = 0.0;
  Vec13 y, yd = Vec13::Zero();
  for (int e = 0; e < n_el_; ++e) {
    y << Eigen::Map<const Vec12>(q + 6 * e), q[nL_];
    W += ElementStrain(e, y, yd, nullptr, nullptr, nullptr);
  }
  return W;
}

Vec6 AncfHoistRopeBody::Momentum(const double* q, const double* v) const {
  const double L = q[nL_], Ld = v[nL_], N = n_el_;
  const double *xs = nullptr, *ws = nullptr;
  GaussPoints01(5, xs, ws);
  Vec3 p = Vec3::Zero(), H = Vec3::Zero();
  for (int e = 0; e < n_el_; ++e) {
    const Eigen::Map<const Vec12> qe(q + 6 * e), ve(v + 6 * e);
    for (int g = 0; g < 5; ++g) {
      const Vec3 r = S0(xs[g]) * qe;
      const Vec3 u = S0(xs[g]) * ve + S1(xs[g]) * qe * ((N - e - xs[g]) * Ld / L);
      const double dm = rhoA_ * ws[g] * L / N;
      p += dm * u;
      H += dm * r.cross(u);
    }
  }
  Vec6 out;
  out << p, H;
  return out;
}

void AncfHoistRopeBody::BodyFramePose(const double*, Vec3& p_WB, Mat3& R_WB) const {
  p_WB = data_.start_W;
  R_WB = R_W0_;
}

Vec3 AncfHoistRopeBody::MaterialPoint(const double* q, double sigma) const {
  const double L = q[nL_], N = n_el_;
  const double eta = std::clamp(N - sigma * N / L, 0.0, N);
  const int e = std::min(n_el_ - 1, static_cast<int>(std::floor(eta)));
  return S0(eta - e) * Eigen::Map<const Vec12>(q + 6 * e);
}

Vec3 AncfHoistRopeBody::CentreLinePoint(const double* q, int k) const {
  const double eta = static_cast<double>(k) / kLinePointsPerElement;
  const int e = std::min(n_el_ - 1, k / kLinePointsPerElement);
  return S0(eta - e) * Eigen::Map<const Vec12>(q + 6 * e);
}

double AncfHoistRopeBody::AxialForce(const double* q, int e) const {
  const BeamSection& s = data_.section;
  const double lam = (S1(0.5) * Eigen::Map<const Vec12>(q + 6 * e)).norm() * n_el_ / q[nL_];
  return s.axial_strain == AxialStrainMeasure::kGreenLagrange ? s.E * s.A * lam * 0.5 * (lam * lam - 1.0)
                                                              : s.E * s.A * (lam - 1.0);
}

}  // namespace flexmb::ancf
