#pragma once
/// \file sparse_lu.h
/// Sparse LU factorization of the (unsymmetric, indefinite) iteration matrix
/// by SuiteSparse KLU. The symbolic analysis is done once per sparsity
/// pattern; numeric factorizations reuse the pivot order (klu_refactor) and
/// fall back to a fresh pivoting factorization when it degrades.

#include <Eigen/SparseCore>

#include "flexmb/model/workspace.h"

namespace flexmb {

/// KLU wrapper for one fixed sparsity pattern.
class SparseLu {
 public:
  SparseLu();
  ~SparseLu();
  SparseLu(const SparseLu&) = delete;
  SparseLu& operator=(const SparseLu&) = delete;

  /// Factorizes A (compressed, square). Returns false if A is singular; then
  /// singular_column() names the first column found dependent.
  bool Factorize(const SparseMat& A);
  /// Solves A x = b in place (b has A.rows() entries).
  void Solve(VecX& b);
  /// Column index reported singular by the last failed factorization, or -1.
  int singular_column() const { return singular_column_; }
  /// Reciprocal condition estimate of the last factorization.
  double rcond() const { return rcond_; }
  /// Drops the symbolic analysis (call when the pattern changes).
  void Reset();

 private:
  struct Impl;
  Impl* impl_;
  int singular_column_ = -1;
  double rcond_ = 0.0;
};

}  // namespace flexmb
