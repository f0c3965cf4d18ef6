#include "flexmb/bodies/flexible_inertia.h"

#include <algorithm>

namespace flexmb {
namespace {

// symmetric 3 x 3 matrix from row k of a stacked contraction (entries 00,
// 11, 22, 10, 20, 21)
Mat3 FlexInertiaUnpack(const Eigen::Matrix<double, Eigen::Dynamic, 6>& g, int k) {
  Mat3 m;
  m << g(k, 0), g(k, 3), g(k, 4), g(k, 3), g(k, 1), g(k, 5), g(k, 4), g(k, 5), g(k, 2);
  return m;
}

}  // namespace

FlexibleInertia::FlexibleInertia(const reduction::InertiaInvariants& inv) : inv_(inv), n_(inv.n) {
  const int n = n_, N = 6 + n_;
  F_.setZero(N);
  Fvb_.setZero(N, 3);
  Fom_.setZero(N, 3);
  Fgb_.setZero(N, 3);
  Fwd_.setZero(N, n);
  Fw_.setZero(N, n);
  Jk_.assign(n, Mat3::Zero());
  C_.setZero(3, n);
  Cdot_.setZero(3, n);
  Ako_.setZero(3, n);
  Ckd_.setZero(3, n);
  Z_.setZero(3, n);
  T_.setZero(3, n);
  Y_.setZero(n, n);
  GW_.setZero(n, 6);
  GWd_.setZero(n, 6);
  Cw_.setZero(3, n);
  gw_at_.setZero(n);
  P_.setZero(n, 6 * n);
  for (int j = 0; j < n; ++j) {
    for (int k = j; k < n; ++k) {
      // P_kj = P_jk is symmetric (moo2[j n + k] = moo2[k n + j]^T)
      const Mat3 P = inv_.moo2[static_cast<size_t>(k) * n + j] + inv_.moo2[static_cast<size_t>(j) * n + k];
      P_(k, 6 * j + 0) = P(0, 0);
      P_(k, 6 * j + 1) = P(1, 1);
      P_(k, 6 * j + 2) = P(2, 2);
      P_(k, 6 * j + 3) = 0.5 * (P(1, 0) + P(0, 1));
      P_(k, 6 * j + 4) = 0.5 * (P(2, 0) + P(0, 2));
      P_(k, 6 * j + 5) = 0.5 * (P(2, 1) + P(1, 2));
    }
  }
  Mw_.setZero(3 * n, n);
  for (int i = 0; i < n; ++i) Mw_.col(i) = Eigen::Map<const Eigen::VectorXd>(inv_.mow1[i].data(), 3 * n);
}

bool FlexibleInertia::HasContraction(const double* w) const {
  return gw_valid_ && std::equal(w, w + n_, gw_at_.data());
}

void FlexibleInertia::ContractSecondOrder(const double* w, const double* wd, const Vec3& om, bool with_w,
                                          bool with_wd) const {
  const int n = n_;
  const Eigen::Map<const Eigen::VectorXd> wv(w, n), wdv(wd, n);
  // Wq weights: 1/2 om^T P om = sum_r c_r p_r
  double c[6] = {0.5 * om(0) * om(0), 0.5 * om(1) * om(1), 0.5 * om(2) * om(2),
                 om(1) * om(0),       om(2) * om(0),       om(2) * om(1)};
  if (with_w) {
    GW_.setZero();
    gw_valid_ = false;
  }
  if (with_wd) GWd_.setZero();
  auto Wq = Fw_.bottomRows(n);
  // column j: the blocks P_kj, k >= j; the entries k > j act on row j too
  for (int j = 0; j < n; ++j) {
    const int len = n - j;
    if (with_wd) Wq.col(j).segment(j, len).setZero();
    for (int r = 0; r < 6; ++r) {
      const auto x = P_.col(6 * j + r).segment(j, len);
      if (with_w) {
        GW_.col(r).segment(j, len).noalias() += w[j] * x;
        GW_(j, r) += x.tail(len - 1).dot(wv.segment(j + 1, len - 1));
      }
      if (with_wd) {
        GWd_.col(r).segment(j, len).noalias() += wd[j] * x;
        GWd_(j, r) += x.tail(len - 1).dot(wdv.segment(j + 1, len - 1));
        Wq.col(j).segment(j, len).noalias() += c[r] * x;
      }
    }
  }
  if (with_wd) {
    // Wq is symmetric: mirror the lower part
    for (int j = 0; j < n; ++j)
      for (int k = j + 1; k < n; ++k) Wq(j, k) = Wq(k, j);
  }
  if (with_w) {
    Eigen::Map<Eigen::VectorXd>(Cw_.data(), 3 * n).noalias() = Mw_ * wv;
    gw_at_ = wv;
    gw_valid_ = true;
  }
}

Mat3 FlexibleInertia::MooDerivative(int k) const { return inv_.moo1[k] + FlexInertiaUnpack(GW_, k); }

void FlexibleInertia::MassMatrix(const double* w, Eigen::Ref<Eigen::MatrixXd> out) const {
  const int n = n_;
  // sum_ij w_i w_j moo2[i n + j] = 1/2 sum_k w_k sum_j w_j P_kj
  if (!HasContraction(w)) ContractSecondOrder(w, nullptr, Vec3::Zero(), true, false);
  Mat3 mvo = inv_.mvo0, moo = inv_.moo0;
  for (int k = 0; k < n; ++k) {
    mvo += w[k] * inv_.mvo1[k];
    moo += w[k] * (inv_.moo1[k] + 0.5 * FlexInertiaUnpack(GW_, k));
  }
  out.block<3, 3>(0, 0) = inv_.mvv;
  out.block<3, 3>(0, 3) = mvo;
  out.block<3, 3>(3, 0) = mvo.transpose();
  out.block<3, 3>(3, 3) = 0.5 * (moo + moo.transpose());
  if (n == 0) return;
  out.block(0, 6, 3, n) = inv_.mvw;
  auto ow = out.block(3, 6, 3, n);
  ow = inv_.mow0 + Cw_;
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
  for (int i = 0; i < n; ++i) {
    A += w[i] * inv_.mvo1[i];
    Adot += wd[i] * inv_.mvo1[i];
    J += w[i] * inv_.moo1[i];
  }
  // moo2 sums through the stacked P: Jk = dJ/dw_k = moo1[k] + sum_j w_j
  // P_kj, J += 1/2 sum_k w_k (Jk - moo1[k]); with tangents T(:, k) =
  // sum_i wd_i P_ik om and Wq(k, j) = 1/2 om^T P_kj om
  const bool with_w = !HasContraction(w);
  if (with_w || tangents) ContractSecondOrder(w, wd, om, with_w, tangents);
  for (int k = 0; k < n; ++k) {
    const Mat3 Gw = FlexInertiaUnpack(GW_, k);
    Jk_[k] = inv_.moo1[k] + Gw;
    J += (0.5 * w[k]) * Gw;
    if (tangents) T_.col(k) = FlexInertiaUnpack(GWd_, k) * om;
  }
  Mat3 Jdot = Mat3::Zero();
  for (int i = 0; i < n; ++i) Jdot += wd[i] * Jk_[i];
  // mow1 in one pass over the stacked Mw_ (C = mow0 + Cw_ is shared with
  // MassMatrix): Cdot, Ckd(:, k) = mow1[k] wd and Y(:, k) = mow1[k]^T om
  const Eigen::Map<const Eigen::VectorXd> wdv(wd, n);
  C_ = inv_.mow0 + Cw_;
  Cdot_.setZero();
  Eigen::Map<Eigen::VectorXd> cdv(Cdot_.data(), 3 * n);
  for (int i = 0; i < n; ++i) {
    const auto col = Mw_.col(i);
    cdv.noalias() += wd[i] * col;
    const Eigen::Map<const Eigen::Matrix3Xd> Xi(col.data(), 3, n);
    Ckd_.col(i).noalias() = Xi * wdv;
    if (tangents) Y_.col(i).noalias() = Xi.transpose() * om;
  }
  const Eigen::MatrixXd& B = inv_.mvw;

  pv_ = Mvv * vb + A * om + B * wdv;
  po_ = A.transpose() * vb + J * om + C_ * wdv;
  const Vec3 oxv = om.cross(vb);
  for (int k = 0; k < n; ++k) Ako_.col(k) = inv_.mvo1[k] * om;

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
  // Fw_'s modal rows hold Wq (ContractSecondOrder)
}

}  // namespace flexmb
