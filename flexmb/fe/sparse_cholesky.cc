#include "flexmb/fe/sparse_cholesky.h"

#include <cholmod.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

#include "flexmb/common/error.h"

namespace flexmb::fe {

namespace {

// A pivot L_kk^2 below this fraction of its diagonal entry A_kk means that
// column k is, to round-off, a combination of the columns eliminated before
// it: a singular matrix. Legitimate ill-conditioning stays far above (a
// cantilever of 1000 beam elements: (h / L)^3 / 4 = 2.5e-10 at its tip).
constexpr double kPivotRatioTolerance = 1e3 * std::numeric_limits<double>::epsilon();

std::string Sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string Name(const DofDescriber& describe, int j) {
  return describe ? describe(j) : "row " + std::to_string(j);
}

}  // namespace

struct SparseCholesky::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  std::vector<int> outer, inner;   // pattern of the analysed upper triangle
  // solve workspaces, reused across calls
  cholmod_dense* x = nullptr;
  cholmod_dense* y = nullptr;
  cholmod_dense* e = nullptr;

  Impl() {
    cholmod_start(&common);
    common.print = 0;
    common.supernodal = CHOLMOD_SUPERNODAL;
    common.final_ll = 1;
  }
  ~Impl() {
    for (cholmod_dense** d : {&x, &y, &e}) {
      if (*d != nullptr) cholmod_free_dense(d, &common);
    }
    if (factor != nullptr) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }

  // diagonal of L in the permuted ordering
  std::vector<double> Diagonal() const {
    const cholmod_factor* l = factor;
    std::vector<double> d(l->n);
    const double* lx = static_cast<const double*>(l->x);
    if (l->is_super) {
      const int* super = static_cast<const int*>(l->super);
      const int* pi = static_cast<const int*>(l->pi);
      const int* px = static_cast<const int*>(l->px);
      for (size_t s = 0; s < l->nsuper; ++s) {
        const int k1 = super[s], k2 = super[s + 1];
        const int nrow = pi[s + 1] - pi[s];
        for (int k = k1; k < k2; ++k) d[k] = lx[px[s] + (k - k1) * nrow + (k - k1)];
      }
    } else {
      const int* lp = static_cast<const int*>(l->p);
      for (size_t k = 0; k < l->n; ++k) d[k] = lx[lp[k]];
    }
    return d;
  }
};

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

void SparseCholesky::Factorize(const SparseMat& a, const std::string& what, const DofDescriber& describe) {
  const Eigen::Index n = a.rows();
  if (a.cols() != n || n == 0) {
    throw NumericalError(what + ": a Cholesky factorization needs a non-empty square matrix (" +
                         std::to_string(a.rows()) + " x " + std::to_string(a.cols()) + ")");
  }
  SparseMat upper = a.triangularView<Eigen::Upper>();
  upper.makeCompressed();
  for (Eigen::Index k = 0; k < upper.nonZeros(); ++k) {
    if (!std::isfinite(upper.valuePtr()[k])) {
      int col = 0;
      while (upper.outerIndexPtr()[col + 1] <= k) ++col;
      throw NumericalError(what + " has a non-finite entry in the column of " + Name(describe, col));
    }
  }
  Impl& m = *impl_;
  cholmod_sparse s{};
  s.nrow = s.ncol = static_cast<size_t>(n);
  s.nzmax = static_cast<size_t>(upper.nonZeros());
  s.p = upper.outerIndexPtr();
  s.i = upper.innerIndexPtr();
  s.x = upper.valuePtr();
  s.stype = 1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;

  // analyse once per pattern
  const bool same_pattern =
      m.factor != nullptr && static_cast<Eigen::Index>(m.outer.size()) == n + 1 &&
      std::equal(m.outer.begin(), m.outer.end(), upper.outerIndexPtr()) &&
      static_cast<Eigen::Index>(m.inner.size()) == upper.nonZeros() &&
      std::equal(m.inner.begin(), m.inner.end(), upper.innerIndexPtr());
  if (!same_pattern) {
    if (m.factor != nullptr) cholmod_free_factor(&m.factor, &m.common);
    n_ = 0;
    perm_ = nullptr;
    m.factor = cholmod_analyze(&s, &m.common);
    if (m.factor == nullptr) {
      throw NumericalError(what + ": CHOLMOD could not analyse the matrix (status " +
                           std::to_string(m.common.status) + ", out of memory?)");
    }
    m.outer.assign(upper.outerIndexPtr(), upper.outerIndexPtr() + n + 1);
    m.inner.assign(upper.innerIndexPtr(), upper.innerIndexPtr() + upper.nonZeros());
  }
  n_ = 0;
  const int ok = cholmod_factorize(&s, m.factor, &m.common);
  if (!ok || m.common.status < CHOLMOD_OK) {
    throw NumericalError(what + ": CHOLMOD failed to factorize (status " + std::to_string(m.common.status) +
                         ", out of memory?)");
  }
  perm_ = static_cast<const int*>(m.factor->Perm);
  auto original = [&](Eigen::Index k) { return perm_ != nullptr ? perm_[k] : static_cast<int>(k); };
  if (m.common.status == CHOLMOD_NOT_POSDEF) {
    const Eigen::Index col = static_cast<Eigen::Index>(m.factor->minor);
    const std::string at = col < n ? " at " + Name(describe, original(col)) : std::string();
    throw NumericalError(what + " is not positive definite: the Cholesky factorization fails" + at +
                         " (a mechanism, a DOF without stiffness, or a negative stiffness)");
  }
  if (!m.factor->is_ll) throw NumericalError(what + ": CHOLMOD returned an LDL' factorization; LL' expected");

  // round-off pivots: singular, but not caught exactly by the factorization
  const std::vector<double> d = m.Diagonal();
  const double* ax = upper.valuePtr();
  const int* ap = upper.outerIndexPtr();
  const int* ai = upper.innerIndexPtr();
  double worst = std::numeric_limits<double>::infinity();
  Eigen::Index worst_k = -1;
  for (Eigen::Index k = 0; k < n; ++k) {
    const int j = original(k);
    // the diagonal entry is the last one of its column in the upper triangle
    const int last = ap[j + 1] - 1;
    const double ajj = last >= ap[j] && ai[last] == j ? ax[last] : 0.0;
    const double ratio = ajj > 0.0 ? d[k] * d[k] / ajj : 0.0;
    if (ratio < worst) {
      worst = ratio;
      worst_k = k;
    }
  }
  if (worst < kPivotRatioTolerance) {
    throw NumericalError(what + " is singular to working precision (a mechanism, or a DOF without stiffness): " +
                         "the pivot of " + Name(describe, original(worst_k)) + " is " + Sci(worst) +
                         " times its diagonal entry");
  }
  n_ = n;
}

double SparseCholesky::FactorNonZeros() const {
  if (n_ == 0) return 0.0;
  const cholmod_factor* l = impl_->factor;
  if (l->is_super) {
    const int* super = static_cast<const int*>(l->super);
    const int* pi = static_cast<const int*>(l->pi);
    double nnz = 0.0;
    for (size_t s = 0; s < l->nsuper; ++s) {
      const double ncol = super[s + 1] - super[s], nrow = pi[s + 1] - pi[s];
      nnz += ncol * nrow - ncol * (ncol - 1) / 2;
    }
    return nnz;
  }
  return static_cast<double>(static_cast<const int*>(l->p)[l->n]);
}

double SparseCholesky::RcondEstimate() const {
  if (n_ == 0) return 0.0;
  return cholmod_rcond(impl_->factor, &impl_->common);
}

Eigen::MatrixXd SparseCholesky::SolveBlock(int sys, const Eigen::MatrixXd& b) const {
  if (n_ == 0) throw NumericalError("sparse Cholesky: solve before a successful factorization");
  if (b.rows() != n_) throw NumericalError("sparse Cholesky: right-hand side of the wrong size");
  Eigen::MatrixXd out(n_, b.cols());
  if (b.cols() == 0) return out;
  // a workspace of its own: block solves may run on several threads at once
  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  cholmod_dense rhs{};
  rhs.nrow = static_cast<size_t>(n_);
  rhs.ncol = static_cast<size_t>(b.cols());
  rhs.nzmax = rhs.nrow * rhs.ncol;
  rhs.d = rhs.nrow;
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense *x = nullptr, *y = nullptr, *e = nullptr;
  const int ok = cholmod_solve2(sys, impl_->factor, &rhs, nullptr, &x, nullptr, &y, &e, &common);
  if (ok) std::memcpy(out.data(), x->x, sizeof(double) * rhs.nzmax);
  for (cholmod_dense** d : {&x, &y, &e}) {
    if (*d != nullptr) cholmod_free_dense(d, &common);
  }
  cholmod_finish(&common);
  if (!ok) throw NumericalError("sparse Cholesky: CHOLMOD solve failed (out of memory?)");
  return out;
}

Eigen::MatrixXd SparseCholesky::Solve(const Eigen::MatrixXd& b) const { return SolveBlock(CHOLMOD_A, b); }

Eigen::MatrixXd SparseCholesky::SolveL(const Eigen::MatrixXd& b) const { return SolveBlock(CHOLMOD_L, b); }

Eigen::MatrixXd SparseCholesky::SolveLt(const Eigen::MatrixXd& b) const { return SolveBlock(CHOLMOD_Lt, b); }

void SparseCholesky::SolveSystem(int sys, const double* x, double* y) const {
  if (n_ == 0) throw NumericalError("sparse Cholesky: solve before a successful factorization");
  Impl& m = *impl_;
  cholmod_dense b{};
  b.nrow = static_cast<size_t>(n_);
  b.ncol = 1;
  b.nzmax = b.nrow;
  b.d = b.nrow;
  b.x = const_cast<double*>(x);
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  if (!cholmod_solve2(sys, m.factor, &b, nullptr, &m.x, nullptr, &m.y, &m.e, &m.common)) {
    throw NumericalError("sparse Cholesky: CHOLMOD triangular solve failed");
  }
  std::copy_n(static_cast<const double*>(m.x->x), n_, y);
}

void SparseCholesky::SolveL(const double* x, double* y) const { SolveSystem(CHOLMOD_L, x, y); }

void SparseCholesky::SolveLt(const double* x, double* y) const { SolveSystem(CHOLMOD_Lt, x, y); }

}  // namespace flexmb::fe
