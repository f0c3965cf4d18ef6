#pragma once
/// \file flexible_inertia.h
/// Inertial and gravity forces of a floating-frame flexible body from its
/// inertia invariants (THEORY sections 4 and 5), in body components, with
/// their analytic partial derivatives. Cost O(n^2) in the number of modes n,
/// independent of the FE mesh; no allocation per call (scratch is sized at
/// construction). Keeps a stacked copy of the second-order invariants moo2
/// (9 n^2 doubles, 1.8 MB at n = 160) so that each evaluation reads them in
/// one pass.
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

  /// Evaluates F (6 + n) and, with `tangents`, the partials below. Inputs are
  /// body components (see the file comment); w and wd point to n values.
  void Evaluate(const Vec3& vb, const Vec3& om, const double* w, const double* wd, const Vec3& gb,
                bool tangents) const;

  /// Mass matrix M(w) (6 + n square, body components, velocity blocks
  /// (vb, om, wd)) into `out`, equal to reduction::MassMatrix to round-off
  /// but from the stacked symmetric moo2 (one matrix-vector product).
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

 private:
  const reduction::InertiaInvariants& inv_;
  int n_;
  // G_(9 k + r, j) = (moo2[k n + j] + moo2[j n + k]) entry r (column-major
  // 3 x 3): every sum over moo2 becomes one matrix product, O(9 n^2)
  Eigen::MatrixXd G_;
  mutable Eigen::MatrixXd GW_;          // G_ w, G_ wd
  // scratch, sized at construction
  mutable Eigen::VectorXd F_;
  mutable MatN3 Fvb_, Fom_, Fgb_;
  mutable Eigen::MatrixXd Fwd_, Fw_;
  mutable Vec3 pv_ = Vec3::Zero(), po_ = Vec3::Zero();
  mutable std::vector<Mat3> Jk_;          // dM_oo/dw_k
  mutable Eigen::Matrix3Xd C_, Cdot_;     // M_ow(w), sum_i wd_i mow1[i]
  mutable Eigen::Matrix3Xd Ako_, Ckd_, Z_, T_;  // mvo1[k] om, mow1[k] wd, dp_o/dw_k, sum_i wd_i (P_ik + P_ki) om
  mutable Eigen::MatrixXd Y_, Wq_;        // Y(:, k) = mow1[k]^T om; Wq(i, k) = om^T P_ik om
};

}  // namespace flexmb
