#pragma once
/// \file flexible_inertia.h
/// Inertial and gravity forces of a floating-frame flexible body from its
/// inertia invariants (THEORY sections 4 and 5), in body components, with
/// their analytic partial derivatives. Cost O(n^2) in the number of modes n,
/// independent of the FE mesh; no allocation per call (scratch is sized at
/// construction). Keeps stacked copies of the invariants so that each
/// evaluation reads them in one pass: the second-order invariants moo2 as the
/// six distinct entries of the symmetric blocks P_kj = moo2[k n + j] +
/// moo2[j n + k] = P_jk, of which only k >= j are read (3 n^2 doubles, 0.6 MB
/// at n = 160), and mow1 as one 3n x n matrix. The contraction G w of the
/// second-order invariants with the modal coordinates is shared between
/// MassMatrix and Evaluate at the same w.
///
/// Variables: vb = R^T v_W (velocity of the frame origin, body components),
/// om (angular velocity, body components), wd (modal velocities), w (modal
/// coordinates), gb = R^T g_W (gravity, body components). With
/// nu = (vb, om, wd), p = M(w) nu and T = 1/2 nu^T M(w) nu the body-component
/// equations are M(w) nudot = Q + k (THEORY section 5). The flexible body uses
/// v_W instead of vb as its first velocity block, vdot_b = R^T a_W - om x vb,
/// so the force computed here is
///   F = M(w) (gb; 0; 0) + k + M(w) (om x vb; 0; 0)
/// whose v rows, turned to world by R, and o, w rows are the generalized
/// inertial and gravity forces of the body's coordinates (elastic and damping
/// forces are added by FlexibleBody).

#include <Eigen/Core>
#include <vector>

#include "flexmb/math/rotation.h"
#include "flexmb/reduction/reduced_body.h"

namespace flexmb {

/// Evaluates F (see the file comment) and its partials from the invariants.
class FlexibleInertia {
 public:
  using MatN3 = Eigen::Matrix<double, Eigen::Dynamic, 3>;

  /// Keeps a reference to `inv` (must outlive this object) and sizes the
  /// scratch for inv.n modes.
  explicit FlexibleInertia(const reduction::InertiaInvariants& inv);

  /// Number of modes.
  int n() const { return n_; }

  /// Evaluates F (6 + n) and, with `tangents`, the partials below (without,
  /// only F, p_v and p_o are updated). Inputs are
  /// body components (see the file comment); w and wd point to n values.
  void Evaluate(const Vec3& vb, const Vec3& om, const double* w, const double* wd, const Vec3& gb,
                bool tangents) const;

  /// Mass matrix M(w) (6 + n square, body components, velocity blocks
  /// (vb, om, wd)) into `out`, equal to reduction::MassMatrix to round-off
  /// but from the stacked symmetric moo2 (one pass).
  void MassMatrix(const double* w, Eigen::Ref<Eigen::MatrixXd> out) const;

  /// Results of the last Evaluate call.
  const Eigen::VectorXd& F() const { return F_; }   ///< (6 + n) force
  const MatN3& dF_dvb() const { return Fvb_; }      ///< (6 + n) x 3
  const MatN3& dF_dom() const { return Fom_; }      ///< (6 + n) x 3
  const MatN3& dF_dgb() const { return Fgb_; }      ///< (6 + n) x 3
  const Eigen::MatrixXd& dF_dwd() const { return Fwd_; }  ///< (6 + n) x n
  const Eigen::MatrixXd& dF_dw() const { return Fw_; }    ///< (6 + n) x n

  /// Generalized momentum parts of the last Evaluate: p_v = M_vv vb + M_vo om
  /// + M_vw wd [kg m/s] and p_o (angular momentum about the frame origin)
  /// [kg m^2/s], body components.
  const Vec3& p_v() const { return pv_; }
  const Vec3& p_o() const { return po_; }

  /// dM_oo/dw_k = moo1[k] + sum_j w_j (moo2[k n + j] + moo2[j n + k]) at the
  /// w of the last MassMatrix or Evaluate call, from their shared
  /// contraction of the second-order invariants (O(1) per k).
  Mat3 MooDerivative(int k) const;

 private:
  // GW_ (n x 6) = contraction of the stacked moo2 with w (column r: entry r
  // of the symmetric 3 x 3 blocks, order 00, 11, 22, 10, 20, 21); with
  // `with_wd` also GWd_ with wd and, into Fw_'s modal rows, Wq(k, j) =
  // 1/2 om^T P_kj om; with `with_w` also Cw_; `with_w` false keeps GW_, Cw_
  void ContractSecondOrder(const double* w, const double* wd, const Vec3& om, bool with_w, bool with_wd) const;
  // true if GW_ holds the contraction with w
  bool HasContraction(const double* w) const;

  const reduction::InertiaInvariants& inv_;
  int n_;
  // P_(k, 6 j + r) = entry r of P_kj for k >= j (rows above j unused)
  Eigen::MatrixXd P_;
  // Mw_(3 j + r, i) = mow1[i](r, j): column i is mow1[i] column-major
  Eigen::MatrixXd Mw_;
  mutable Eigen::Matrix<double, Eigen::Dynamic, 6> GW_, GWd_;
  mutable Eigen::Matrix3Xd Cw_;    // sum_i w_i mow1[i], with GW_
  mutable Eigen::VectorXd gw_at_;  // the w of GW_ and Cw_
  mutable bool gw_valid_ = false;
  // scratch, sized at construction
  mutable Eigen::VectorXd F_;
  mutable MatN3 Fvb_, Fom_, Fgb_;
  mutable Eigen::MatrixXd Fwd_, Fw_;
  mutable Vec3 pv_ = Vec3::Zero(), po_ = Vec3::Zero();
  mutable std::vector<Mat3> Jk_;          // dM_oo/dw_k
  mutable Eigen::Matrix3Xd C_, Cdot_;     // M_ow(w), sum_i wd_i mow1[i]
  mutable Eigen::Matrix3Xd Ako_, Ckd_, Z_, T_;  // mvo1[k] om, mow1[k] wd, dp_o/dw_k, sum_i wd_i (P_ik + P_ki) om
  mutable Eigen::MatrixXd Y_;             // Y(:, k) = mow1[k]^T om
};

}  // namespace flexmb
