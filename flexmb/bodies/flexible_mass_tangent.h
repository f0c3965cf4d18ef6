#pragma once
/// \file flexible_mass_tangent.h
/// The derivative d(M(q) a)/dq of a floating-frame flexible body's mass
/// matrix times a fixed acceleration, the term of the iteration matrix that
/// a configuration-dependent mass adds (stiffness coefficient times it;
/// issue 5, "analytic tangent contributions (mass, ...)"), added to the
/// iteration matrix by AddMassTangents (solver/assembler.h).
///
/// Coordinates as FlexibleBody (bodies/flexible_body.h): q = (r_W, R, w),
/// velocities (v_W, om_B, wd), tangent increments dx = (dr_W, dtheta_B, dw)
/// with R <- R exp(dtheta). The body's mass matrix is M(q) = T^T M_B(w) T,
/// T = diag(R^T, I, I), M_B the invariants' matrix (THEORY section 4,
/// reduction::MassMatrix). With a_B = T a = (R^T a_v, a_o, a_w) and
/// y = M_B a_B:
///   columns dw_i:     T^T (dM_B/dw_i) a_B, where (dM_B/dw_i) a_B has the
///                     rows v: mvo1[i] a_o; o: mvo1[i]^T a_v + (moo1[i] +
///                     sum_j (moo2[i n + j] + moo2[j n + i]) w_j) a_o +
///                     mow1[i] a_w; w: mow1[i]^T a_o;
///   columns dtheta:   rows v: -R skew(y_v) + R M_B[v, v] skew(R^T a_v),
///                     rows o, w: M_B[o|w, v] skew(R^T a_v);
///   columns dr:       zero.
/// M_B(w) and the sums over moo2 come from the body's FlexibleInertia, whose
/// contraction of the second-order invariants with w is shared with the
/// mass matrix and the forces at the same w (issue 23). Cost O(n^2) per
/// call (O(n) once that contraction exists), no allocation (scratch sized
/// at construction).

#include <Eigen/Core>

#include "flexmb/bodies/flexible_inertia.h"
#include "flexmb/reduction/reduced_body.h"

namespace flexmb {

/// Evaluates d(M(q) a)/dq of one flexible body; see the file comment.
class FlexibleMassTangent {
 public:
  /// Keeps references to `inv` and to `inertia`, the body's evaluator of
  /// the same invariants (both must outlive this object).
  FlexibleMassTangent(const reduction::InertiaInvariants& inv, const FlexibleInertia& inertia);

  /// Adds `scale` d(M(q) a)/dq to K ((6 + n) square; rows the velocity
  /// components v_W, om_B, wd; columns the increments dr_W, dtheta_B, dw)
  /// for the orientation R (body to world), modal coordinates w (n) and the
  /// acceleration a (6 + n, in the velocity components).
  void Add(const Eigen::Matrix3d& R, const double* w, const double* a, double scale,
           Eigen::Ref<Eigen::MatrixXd> K) const;

 private:
  const reduction::InertiaInvariants& inv_;
  const FlexibleInertia& inertia_;
  int n_;
  mutable Eigen::MatrixXd mb_;  // M_B(w)
  mutable Eigen::VectorXd ab_, y_, col_;
};

}  // namespace flexmb
