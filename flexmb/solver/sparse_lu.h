#pragma once
/// \file sparse_lu.h
/// LU factorization of the (unsymmetric, indefinite) iteration matrix.
/// Sparse matrices go to SuiteSparse KLU: the symbolic analysis is done once
/// per sparsity pattern; numeric factorizations reuse the pivot order
/// (klu_refactor) and fall back to a fresh pivoting factorization when it
/// degrades. Large, mostly dense matrices (a floating-frame flexible body with
/// many modes fills its whole (6 + n) x (6 + n) block) are factorized instead
/// as a dense copy by a blocked LU with partial pivoting (LAPACK dgetrf's
/// order, Eigen kernels), several times faster than KLU there (measured in
/// docs/PERFORMANCE.md, "Flexible body step rate"). Both paths allocate only
/// when the pattern changes, for any size (the dense path keeps its product
/// blocks small enough for Eigen's stack buffers).

#include <Eigen/SparseCore>

#include "flexmb/model/workspace.h"

namespace flexmb {

/// Copies the square sparse A into the dense a (sized n x n by the caller)
/// as SparseLu's dense path does: a fully stored column in one piece (the
/// rows of Eigen's storage are in order), others scattered into a zeroed
/// column.
void CopyToDense(const SparseMat& A, Eigen::MatrixXd& a);

/// LU factorization (KLU, or dense partial pivoting) for one fixed sparsity
/// pattern.
class SparseLu {
 public:
  /// The dense path is taken for matrices with at least kDenseMinRows rows
  /// and at least kDenseMinFill * rows^2 stored entries.
  static constexpr int kDenseMinRows = 48;
  /// See kDenseMinRows.
  static constexpr double kDenseMinFill = 0.25;

  /// Which factorization to use: by size and fill (kAuto, see kDenseMinRows),
  /// always KLU, or always dense (tests and bench/lu_threshold.cc).
  enum class Path { kAuto, kKlu, kDense };

  explicit SparseLu(Path path = Path::kAuto);
  ~SparseLu();
  SparseLu(const SparseLu&) = delete;
  SparseLu& operator=(const SparseLu&) = delete;

  /// Factorizes A (compressed, square). Returns false if A is singular; then
  /// singular_column() names the first column found dependent. KLU reports a
  /// column whose pivot is exactly zero; the dense path reports the first
  /// column k whose pivot |u_kk| <= rows * eps * max_i |a_ik| (the pivot is
  /// round-off of the column's own size: A(:, k) depends on A(:, 0..k-1)).
  bool Factorize(const SparseMat& A);
  /// Solves A x = b in place (b has A.rows() entries).
  void Solve(VecX& b);
  /// Column index reported singular by the last failed factorization, or -1.
  int singular_column() const { return singular_column_; }
  /// Reciprocal condition estimate of the last factorization: min |u_kk| /
  /// max |u_kk| over the pivots of U (KLU's klu_rcond; the same on the dense
  /// path).
  double rcond() const { return rcond_; }
  /// True when the last pattern was factorized by the dense path.
  bool dense() const;
  /// Drops the symbolic analysis (call when the pattern changes).
  void Reset();

 private:
  struct Impl;
  Impl* impl_;
  Path path_;
  int singular_column_ = -1;
  double rcond_ = 0.0;
};

}  // namespace flexmb
