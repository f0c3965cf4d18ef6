#include "flexmb/bodies/flexible_inertia.h"

namespace flexmb {

FlexibleInertia::FlexibleInertia(const reduction::InertiaInvariants& inv) : inv_(inv), n_(inv.n) {
  const int N = 6 + n_;
  F_.setZero(N);
  Fvb_.setZero(N, 3);
  Fom_.setZero(N, 3);
  Fgb_.setZero(N, 3);
  Fwd_.setZero(N, n_);
  Fw_.setZero(N, n_);
  Jk_.assign(n_, Mat3::Zero());
  C_.setZero(3, n_);
  Cdot_.setZero(3, n_);
  Ako_.setZero(3, n_);
  Ckd_.setZero(3, n_);
  Z_.setZero(3, n_);
  T_.setZero(3, n_);
  Y_.setZero(n_, n_);
  Wq_.setZero(n_, n_);
  G_.setZero(9 * n_, n_);
  for (int k = 0; k < n_; ++k) {
    for (int j = 0; j < n_; ++j) {
      const Mat3 P = inv_.moo2[static_cast<size_t>(k) * n_ + j] + inv_.moo2[static_cast<size_t>(j) * n_ + k];
      G_.block<9, 1>(9 * k, j) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(P.data());
    }
  }
  GW_.setZero(9 * n_, 2);
}

void FlexibleInertia::MassMatrix(const double* w, Eigen::Ref<Eigen::MatrixXd> out) const {
  const int n = n_;
  const Eigen::Map<const Eigen::VectorXd> wv(w, n);
  // sum_ij w_i w_j moo2[i n + j] = 1/2 sum_k w_k sum_j w_j (G_ block k, j)
  GW_.col(0).noalias() = G_ * wv;
  Mat3 mvo = inv_.mvo0, moo = inv_.moo0;
  for (int k = 0; k < n; ++k) {
    mvo += w[k] * inv_.mvo1[k];
    moo += w[k] * (inv_.moo1[k] + 0.5 * Eigen::Map<const Mat3>(GW_.col(0).data() + 9 * k));
  }
  out.block<3, 3>(0, 0) = inv_.mvv;
  out.block<3, 3>(0, 3) = mvo;
  out.block<3, 3>(3, 0) = mvo.transpose();
  out.block<3, 3>(3, 3) = 0.5 * (moo + moo.transpose());
  if (n == 0) return;
  out.block(0, 6, 3, n) = inv_.mvw;
  auto ow = out.block(3, 6, 3, n);
  ow = inv_.mow0;
  for (int k = 0; k < n; ++k) ow += w[k] * inv_.mow1[k];
  out.block(6, 0, n, 3) = inv_.mvw.transpose();
  out.block(6, 3, n, 3) = ow.transpose();
  out.block(6, 6, n, n) = inv_.mww;
}

void FlexibleInertia::Evaluate(const Vec3& vb, const Vec3& om, const double* w, const double* wd,
                               const Vec3& gb, bool tangents) const {
  const int n = n_;
  const Mat3& Mvv = inv_.mvv;
  // blocks of M(w) and their rates: A = M_vo, J = M_oo, C = M_ow
  Mat3 A = inv_.mvo0, Adot = Mat3::Zero(), J = inv_.moo0;
  C_ = inv_.mow0;
  Cdot_.setZero();
  for (int i = 0; i < n; ++i) {
    A += w[i] * inv_.mvo1[i];
    Adot += wd[i] * inv_.mvo1[i];
    J += w[i] * inv_.moo1[i];
    Jk_[i] = inv_.moo1[i];
    C_.noalias() += w[i] * inv_.mow1[i];
    Cdot_.noalias() += wd[i] * inv_.mow1[i];
  }
  // moo2 sums through G_: Jk = dJ/dw_k = moo1[k] + sum_j w_j (P_kj + P_jk),
  // J += 1/2 sum_k w_k (Jk - moo1[k]); with tangents T(:, k) = sum_i wd_i
  // (P_ik + P_ki) om and Wq(k, j) = om^T P_kj om = 1/2 om^T (G_ block k, j) om
  // one pass over G_ (column j: the n blocks k, j, kept in cache for the
  // three uses) instead of one per product
  const Mat3 oo = 0.5 * om * om.transpose();
  const Eigen::Map<const Eigen::Matrix<double, 1, 9>> o9(oo.data());
  GW_.setZero();
  for (int j = 0; j < n; ++j) {
    const auto g = G_.col(j);
    GW_.col(0).noalias() += w[j] * g;
    if (!tangents) continue;
    GW_.col(1).noalias() += wd[j] * g;
    Wq_.col(j).transpose().noalias() = o9 * Eigen::Map<const Eigen::Matrix<double, 9, Eigen::Dynamic>>(g.data(), 9, n);
  }
  for (int k = 0; k < n; ++k) {
    const Eigen::Map<const Mat3> Gw(GW_.col(0).data() + 9 * k);
    Jk_[k] += Gw;
    J += (0.5 * w[k]) * Gw;
    if (tangents) T_.col(k) = Eigen::Map<const Mat3>(GW_.col(1).data() + 9 * k) * om;
  }
  Mat3 Jdot = Mat3::Zero();
  for (int i = 0; i < n; ++i) Jdot += wd[i] * Jk_[i];
  const Eigen::Map<const Eigen::VectorXd> wdv(wd, n);
  const Eigen::MatrixXd& B = inv_.mvw;

  pv_ = Mvv * vb + A * om + B * wdv;
  po_ = A.transpose() * vb + J * om + C_ * wdv;
  const Vec3 oxv = om.cross(vb);
  for (int k = 0; k < n; ++k) {
    Ako_.col(k) = inv_.mvo1[k] * om;
    Ckd_.col(k).noalias() = inv_.mow1[k] * wdv;
    Y_.col(k).noalias() = inv_.mow1[k].transpose() * om;
  }

  // F = M (gb; 0; 0) + k + M (om x vb; 0; 0)
  F_.head<3>() = Mvv * gb - Adot * om - om.cross(pv_) + Mvv * oxv;
  F_.segment<3>(3) = A.transpose() * (gb + oxv) - Adot.transpose() * vb - Jdot * om - Cdot_ * wdv -
                     om.cross(po_) - vb.cross(pv_);
  const Vec3 gx = gb + oxv;
  for (int i = 0; i < n; ++i) {
    F_(6 + i) = B.col(i).dot(gx) - Cdot_.col(i).dot(om) + vb.dot(Ako_.col(i)) +
                0.5 * om.dot(Jk_[i] * om) + om.dot(Ckd_.col(i));
  }
  if (!tangents) return;

  for (int k = 0; k < n; ++k) Z_.col(k) = inv_.mvo1[k].transpose() * vb + Jk_[k] * om + Ckd_.col(k);
  const Mat3 So = Skew(om), Sv = Skew(vb);
  const Mat3 At = A.transpose();

  // d/dvb
  Fvb_.topRows<3>() = -So * Mvv + Mvv * So;
  Fvb_.middleRows<3>(3) = -Adot.transpose() - So * At + Skew(pv_) - Sv * Mvv + At * So;
  Fvb_.bottomRows(n).noalias() = Ako_.transpose();
  Fvb_.bottomRows(n).noalias() += B.transpose() * So;
  // d/dom
  Fom_.topRows<3>() = -Adot - So * A + Skew(pv_) - Mvv * Sv;
  Fom_.middleRows<3>(3) = -Jdot - So * J + Skew(po_) - Sv * A - At * Sv;
  Fom_.bottomRows(n).noalias() = Z_.transpose() - Cdot_.transpose();
  Fom_.bottomRows(n).noalias() -= B.transpose() * Sv;
  // d/dgb
  Fgb_.topRows<3>() = Mvv;
  Fgb_.middleRows<3>(3) = At;
  Fgb_.bottomRows(n).noalias() = B.transpose();
  // d/dwd
  Fwd_.topRows<3>() = -Ako_;
  Fwd_.topRows<3>().noalias() -= So * B;
  Fwd_.middleRows<3>(3) = -Z_ - Cdot_;
  Fwd_.middleRows<3>(3).noalias() -= So * C_;
  Fwd_.middleRows<3>(3).noalias() -= Sv * B;
  Fwd_.bottomRows(n) = Y_.transpose() - Y_;
  // d/dw
  Fw_.topRows<3>().noalias() = -So * Ako_;
  for (int k = 0; k < n; ++k) {
    const Mat3& Ak = inv_.mvo1[k];
    Fw_.block<3, 1>(3, k) = Ak.transpose() * gx - T_.col(k) - So * Z_.col(k) - Sv * Ako_.col(k);
  }
  Fw_.bottomRows(n) = Wq_;
}

}  // namespace flexmb
