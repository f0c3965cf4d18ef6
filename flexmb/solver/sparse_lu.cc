#include "flexmb/solver/sparse_lu.h"

#include <klu.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <utility>
#include <limits>

namespace flexmb {
namespace {

// panel width and largest block side of the trailing products of DenseLu
constexpr int kDenseLuPanel = 16;
constexpr int kDenseLuChunk = 512;

// In place LU with partial pivoting of the square column-major a, in
// LAPACK dgetrf's right-looking blocked order: P a = L U (unit L below the
// diagonal, U on and above), row k swapped with row piv(k) at step k (whole
// rows). The trailing updates are products of at most chunk x panel and
// panel x chunk blocks, whose packing buffers (16 x 512 doubles, 64 KB)
// Eigen keeps on the stack (below EIGEN_STACK_ALLOCATION_LIMIT, 128 KB):
// no allocation for any size, unlike PartialPivLU's blocked path. A zero
// pivot leaves its column unscaled (the caller tests the pivots).
void DenseLu(Eigen::MatrixXd& a, Eigen::VectorXi& piv) {
  const int n = static_cast<int>(a.rows());
  for (int k0 = 0; k0 < n; k0 += kDenseLuPanel) {
    const int nb = std::min(kDenseLuPanel, n - k0);
    // the panel (columns k0 .. k0 + nb - 1), unblocked
    for (int k = k0; k < k0 + nb; ++k) {
      Eigen::Index p = 0;
      a.col(k).tail(n - k).cwiseAbs().maxCoeff(&p);
      p += k;
      piv(k) = static_cast<int>(p);
      if (p != k) a.row(k).swap(a.row(p));
      const int m = n - k - 1, c = k0 + nb - k - 1;
      const double d = a(k, k);
      if (m == 0) continue;
      if (d != 0.0) a.col(k).tail(m) /= d;
      if (c > 0) a.block(k + 1, k + 1, m, c).noalias() -= a.col(k).tail(m) * a.row(k).segment(k + 1, c);
    }
    const int rest = n - k0 - nb;
    if (rest <= 0) break;
    // U12 = L11^-1 A12 and A22 -= L21 U12, in chunks
    const auto L11 = a.block(k0, k0, nb, nb).triangularView<Eigen::UnitLower>();
    for (int c0 = 0; c0 < rest; c0 += kDenseLuChunk) {
      const int nc = std::min(kDenseLuChunk, rest - c0);
      auto U12 = a.block(k0, k0 + nb + c0, nb, nc);
      L11.solveInPlace(U12);
      for (int r0 = 0; r0 < rest; r0 += kDenseLuChunk) {
        const int nr = std::min(kDenseLuChunk, rest - r0);
        a.block(k0 + nb + r0, k0 + nb + c0, nr, nc).noalias() -= a.block(k0 + nb + r0, k0, nr, nb) * U12;
      }
    }
  }
}

}  // namespace

void CopyToDense(const SparseMat& A, Eigen::MatrixXd& a) {
  const int n = static_cast<int>(A.rows());
  const int* outer = A.outerIndexPtr();
  const int* counts = A.innerNonZeroPtr();  // null when compressed
  const int* rows = A.innerIndexPtr();
  const double* values = A.valuePtr();
  for (int j = 0; j < n; ++j) {
    auto col = a.col(j);
    const int b = outer[j], e = counts ? b + counts[j] : outer[j + 1];
    if (e - b == n) {
      col = Eigen::Map<const Eigen::VectorXd>(values + b, n);
    } else {
      col.setZero();
      for (int p = b; p < e; ++p) col(rows[p]) = values[p];
    }
  }
}

struct SparseLu::Impl {
  klu_common common;
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  int n = -1, nnz = -1;
  // dense path, sized when the pattern is set
  bool dense = false, dense_ok = false;
  Eigen::MatrixXd a;  // the factors L and U (DenseLu)
  Eigen::VectorXi piv;
  Eigen::VectorXd col_max;
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
  CopyToDense(A, a);
  for (int j = 0; j < n; ++j) col_max(j) = a.col(j).cwiseAbs().maxCoeff();
  DenseLu(a, piv);
  // negligible pivot: round-off of the column's size -> dependent column
  const double tol = n * std::numeric_limits<double>::epsilon();
  const Eigen::MatrixXd& U = a;
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
      k.piv.setZero(n);
      k.col_max.setZero(n);
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
    // x = U^-1 L^-1 P b in place
    for (int i = 0; i < k.n; ++i)
      if (k.piv(i) != i) std::swap(b(i), b(k.piv(i)));
    k.a.triangularView<Eigen::UnitLower>().solveInPlace(b);
    k.a.triangularView<Eigen::Upper>().solveInPlace(b);
    return;
  }
  klu_solve(k.symbolic, k.numeric, static_cast<int>(b.size()), 1, b.data(), &k.common);
}

}  // namespace flexmb
