#include "flexmb/solver/sparse_lu.h"

#include <klu.h>

namespace flexmb {

struct SparseLu::Impl {
  klu_common common;
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  const int* pattern_outer = nullptr;  // pattern identity of the analysis
  int n = -1, nnz = -1;
  void Free() {
    if (numeric) klu_free_numeric(&numeric, &common);
    if (symbolic) klu_free_symbolic(&symbolic, &common);
    numeric = nullptr;
    symbolic = nullptr;
    n = nnz = -1;
  }
};

SparseLu::SparseLu() : impl_(new Impl) { klu_defaults(&impl_->common); }

SparseLu::~SparseLu() {
  impl_->Free();
  delete impl_;
}

void SparseLu::Reset() { impl_->Free(); }

bool SparseLu::Factorize(const SparseMat& A) {
  Impl& k = *impl_;
  const int n = static_cast<int>(A.rows());
  const int nnz = static_cast<int>(A.nonZeros());
  auto* Ap = const_cast<int*>(A.outerIndexPtr());
  auto* Ai = const_cast<int*>(A.innerIndexPtr());
  auto* Ax = const_cast<double*>(A.valuePtr());
  singular_column_ = -1;
  if (n != k.n || nnz != k.nnz || k.symbolic == nullptr) {
    k.Free();
    k.symbolic = klu_analyze(n, Ap, Ai, &k.common);
    if (!k.symbolic) return false;
    k.n = n;
    k.nnz = nnz;
  }
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
  klu_solve(impl_->symbolic, impl_->numeric, static_cast<int>(b.size()), 1, b.data(), &impl_->common);
}

}  // namespace flexmb
