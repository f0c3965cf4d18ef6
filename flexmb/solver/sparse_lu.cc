#include "flexmb/solver/sparse_lu.h"

#include <klu.h>

#include <Eigen/LU>
#include <cmath>
#include <limits>

namespace flexmb {

struct SparseLu::Impl {
  klu_common common;
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  int n = -1, nnz = -1;
  // dense path, sized when the pattern is set
  bool dense = false, dense_ok = false;
  Eigen::MatrixXd a;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  Eigen::VectorXd col_max, tmp;
  void Free() {
    if (numeric) klu_free_numeric(&numeric, &common);
    if (symbolic) klu_free_symbolic(&symbolic, &common);
    numeric = nullptr;
    symbolic = nullptr;
    n = nnz = -1;
    dense = dense_ok = false;
  }
  bool FactorizeDense(const SparseMat& A, int& singular_column, double& rcond);
};

SparseLu::SparseLu(Path path) : impl_(new Impl), path_(path) { klu_defaults(&impl_->common); }

SparseLu::~SparseLu() {
  impl_->Free();
  delete impl_;
}

void SparseLu::Reset() { impl_->Free(); }

bool SparseLu::dense() const { return impl_->dense; }

bool SparseLu::Impl::FactorizeDense(const SparseMat& A, int& singular_column, double& rcond) {
  dense_ok = false;
  a.setZero();
  col_max.setZero();
  for (int j = 0; j < n; ++j) {
    for (SparseMat::InnerIterator it(A, j); it; ++it) {
      a(it.row(), j) = it.value();
      col_max(j) = std::max(col_max(j), std::abs(it.value()));
    }
  }
  lu.compute(a);
  // negligible pivot: round-off of the column's size -> dependent column
  const double tol = n * std::numeric_limits<double>::epsilon();
  const auto& U = lu.matrixLU();
  double umin = std::numeric_limits<double>::infinity(), umax = 0.0;
  int kmin = -1;
  for (int k = 0; k < n; ++k) {
    const double u = std::abs(U(k, k));
    // written so that a NaN pivot (a NaN or Inf entry in A) is singular too
    if (!(u > tol * col_max(k))) {
      singular_column = k;
      rcond = 0.0;
      return false;
    }
    if (u < umin) {
      umin = u;
      kmin = k;
    }
    umax = std::max(umax, u);
  }
  rcond = umax > 0.0 ? umin / umax : 0.0;
  if (!(rcond >= 1e-16)) {
    singular_column = kmin;
    return false;
  }
  dense_ok = true;
  return true;
}

bool SparseLu::Factorize(const SparseMat& A) {
  Impl& k = *impl_;
  const int n = static_cast<int>(A.rows());
  const int nnz = static_cast<int>(A.nonZeros());
  auto* Ap = const_cast<int*>(A.outerIndexPtr());
  auto* Ai = const_cast<int*>(A.innerIndexPtr());
  auto* Ax = const_cast<double*>(A.valuePtr());
  singular_column_ = -1;
  if (n != k.n || nnz != k.nnz || (k.symbolic == nullptr && !k.dense)) {
    k.Free();
    if (path_ == Path::kDense || (path_ == Path::kAuto && n >= kDenseMinRows &&
                                   nnz >= kDenseMinFill * static_cast<double>(n) * n)) {
      k.dense = true;
      k.a.setZero(n, n);
      k.lu = Eigen::PartialPivLU<Eigen::MatrixXd>(n);
      k.col_max.setZero(n);
      k.tmp.setZero(n);
    } else {
      k.symbolic = klu_analyze(n, Ap, Ai, &k.common);
      if (!k.symbolic) return false;
    }
    k.n = n;
    k.nnz = nnz;
  }
  if (k.dense) return k.FactorizeDense(A, singular_column_, rcond_);
  // try to reuse the pivot order; refactor fails or degrades -> fresh factor
  if (k.numeric) {
    if (klu_refactor(Ap, Ai, Ax, k.symbolic, k.numeric, &k.common) && klu_rcond(k.symbolic, k.numeric, &k.common) &&
        k.common.rcond > 1e-14) {
      rcond_ = k.common.rcond;
      return true;
    }
    klu_free_numeric(&k.numeric, &k.common);
  }
  k.numeric = klu_factor(Ap, Ai, Ax, k.symbolic, &k.common);
  if (!k.numeric || k.common.status == KLU_SINGULAR) {
    singular_column_ = static_cast<int>(k.common.singular_col);
    if (k.numeric) klu_free_numeric(&k.numeric, &k.common);
    return false;
  }
  klu_rcond(k.symbolic, k.numeric, &k.common);
  rcond_ = k.common.rcond;
  if (rcond_ < 1e-16) {
    klu_free_numeric(&k.numeric, &k.common);
    return false;
  }
  return true;
}

void SparseLu::Solve(VecX& b) {
  Impl& k = *impl_;
  if (k.dense) {
    // x = U^-1 L^-1 P b, through the preallocated tmp (no temporaries)
    k.tmp.noalias() = k.lu.permutationP() * b;
    k.lu.matrixLU().triangularView<Eigen::UnitLower>().solveInPlace(k.tmp);
    k.lu.matrixLU().triangularView<Eigen::Upper>().solveInPlace(k.tmp);
    b = k.tmp;
    return;
  }
  klu_solve(k.symbolic, k.numeric, static_cast<int>(b.size()), 1, b.data(), &k.common);
}

}  // namespace flexmb
