#pragma once
/// \file shift_invert.h
/// What the two shift-invert eigen solvers (Spectra in modal.cc, block
/// Lanczos in block_lanczos.cc) share: the symmetric shift-inverted operator
/// on a CHOLMOD factorization, the checks of a request, and the final
/// Rayleigh-Ritz step on K and M.
///
/// With P (K - sigma M) P^T = L L^T, K phi = lambda M phi becomes C y = nu y,
/// C = L^{-1} P M P^T L^{-T}, nu = 1 / (lambda - sigma), phi = P^T L^{-T} y.
/// Each application costs one pair of triangular solves and one product with
/// M; inner products are Euclidean, and a singular M is harmless.

#include <Eigen/Core>
#include <string>

#include "flexmb/fe/modal.h"
#include "flexmb/fe/sparse_cholesky.h"

namespace flexmb::fe {

/// C = L^{-1} P M P^T L^{-T} on one vector (the interface Spectra wants) or
/// on a dense block. Holds references to M and the factor.
class ShiftInvertOperator {
 public:
  using Scalar = double;

  ShiftInvertOperator(const SparseMat& m, const SparseCholesky& factor);

  /// Size n.
  Eigen::Index rows() const { return n_; }
  /// Size n.
  Eigen::Index cols() const { return n_; }

  /// y = C x for one vector; reuses internal storage (not thread-safe).
  void perform_op(const double* x_in, double* y_out) const;

  /// C V for a dense n x p block: one pass over the factor and over M.
  Eigen::MatrixXd Apply(const Eigen::MatrixXd& v) const;

  /// Mode shapes phi = P^T L^{-T} Y from eigenvectors Y of C (columns).
  Eigen::MatrixXd Recover(const Eigen::MatrixXd& y) const;

 private:
  Eigen::Index Perm(Eigen::Index k) const {
    const int* p = factor_.Permutation();
    return p != nullptr ? p[k] : k;
  }

  const SparseMat& m_;
  const SparseCholesky& factor_;
  Eigen::Index n_;
  mutable Eigen::VectorXd work_;
  mutable Eigen::VectorXd product_;
};

/// Checks a request for `count` modes of K, M with the factorization of
/// K - shift M: sizes agree, 1 <= count < n, shift <= 0, tolerance > 0.
/// Throws InputError naming `what`.
void CheckModalRequest(const SparseMat& K, const SparseMat& M, const SparseCholesky& factor, double shift,
                       int count, double tolerance, const std::string& what);

/// Checks the converged eigenvalues nu of C (all modes must have mass:
/// nu > 0 well above round-off), then refines the mode shapes phi (n x
/// count) by a Rayleigh-Ritz step on K and M: M-orthonormal modes with
/// ascending frequencies [Hz]; a round-off negative eigenvalue lambda gives
/// the negative frequency -sqrt(-lambda) / 2 pi. Throws NumericalError
/// naming `what`.
ModalResult RayleighRitzModes(const SparseMat& K, const SparseMat& M, const Eigen::VectorXd& nu,
                              const Eigen::MatrixXd& phi, const std::string& what);

}  // namespace flexmb::fe
