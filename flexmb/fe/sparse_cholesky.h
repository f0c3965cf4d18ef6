#pragma once
/// \file sparse_cholesky.h
/// Supernodal sparse Cholesky factorization P A P^T = L L^T of a symmetric
/// positive definite matrix (CHOLMOD, int indices, fill-reducing ordering
/// chosen by CHOLMOD), with solves for many right-hand sides at once and the
/// separate triangular and permutation steps a shift-invert eigen solver
/// needs. CHOLMOD itself stays out of this header.

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>

#include "flexmb/fe/assembly.h"

namespace flexmb::fe {

/// Names row/column j of a factorized matrix for error messages, e.g.
/// "node 1204 component rx".
using DofDescriber = std::function<std::string(int)>;

/// Owns one CHOLMOD workspace and factor. The block solves (Solve, and
/// SolveL / SolveLt of a dense block) use a workspace of their own per call
/// and may run on several threads at once; the single-vector SolveL /
/// SolveLt reuse the internal workspace and must not. Movable, not copyable.
class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Factorizes A (square, symmetric; only its upper triangle is read). The
  /// symbolic analysis (ordering, supernodes) is done on the first call and
  /// reused as long as the size stays the same, so a second matrix with the
  /// same pattern (e.g. another shift) costs only the numeric step. `what`
  /// names the matrix in messages ("K_ii"), `describe` names its DOF.
  /// Throws NumericalError if A is not positive definite, naming the DOF of
  /// the first failing pivot, or if a pivot is at round-off level relative
  /// to its diagonal entry (a singular matrix that the factorization did not
  /// catch exactly: a mechanism), naming that DOF.
  void Factorize(const SparseMat& a, const std::string& what, const DofDescriber& describe = {});

  /// Size n of the factorized matrix (0 before Factorize).
  Eigen::Index rows() const { return n_; }
  /// Non-zeros of L (fill) after Factorize.
  double FactorNonZeros() const;
  /// (min_k L_kk / max_k L_kk)^2, CHOLMOD's cheap reciprocal condition estimate.
  double RcondEstimate() const;

  /// X = A^{-1} B for a dense n x k block, all columns in one CHOLMOD call
  /// (supernodal BLAS-3 triangular solves).
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& b) const;

  /// Fill-reducing permutation: row k of P A P^T is row perm[k] of A
  /// (pointer to n ints, valid while the factor lives).
  const int* Permutation() const { return perm_; }
  /// y = L^{-1} x (permuted ordering; x and y of length n, may alias).
  void SolveL(const double* x, double* y) const;
  /// y = L^{-T} x (permuted ordering; x and y of length n, may alias).
  void SolveLt(const double* x, double* y) const;
  /// L^{-1} B for a dense n x k block (permuted ordering), one CHOLMOD call.
  Eigen::MatrixXd SolveL(const Eigen::MatrixXd& b) const;
  /// L^{-T} B for a dense n x k block (permuted ordering), one CHOLMOD call.
  Eigen::MatrixXd SolveLt(const Eigen::MatrixXd& b) const;

 private:
  struct Impl;
  void SolveSystem(int sys, const double* x, double* y) const;
  Eigen::MatrixXd SolveBlock(int sys, const Eigen::MatrixXd& b) const;
  std::unique_ptr<Impl> impl_;
  Eigen::Index n_ = 0;
  const int* perm_ = nullptr;
};

}  // namespace flexmb::fe
