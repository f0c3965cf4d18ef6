#include "flexmb/fe/modal.h"

#include <cholmod.h>

#include <Eigen/Dense>
#include <Spectra/SymEigsSolver.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "flexmb/common/error.h"

namespace flexmb::fe {

namespace {

const char* const kComponentName[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};

// names a free DOF by its node (position in the mesh's node list) and component
std::string DescribeFreeDof(const DofMap& dofs, int f) {
  for (size_t n = 0; n < dofs.free.size(); ++n) {
    for (int c = 0; c < 6; ++c) {
      if (dofs.free[n][c] == f) {
        return "free DOF " + std::to_string(f) + " (node #" + std::to_string(n) + " of the mesh's node list, " +
               kComponentName[c] + ")";
      }
    }
  }
  return "free DOF " + std::to_string(f);
}

// The shift-inverted problem in symmetric form. With the supernodal CHOLMOD
// factorization P (K - sigma M) P^T = L L^T, K phi = lambda M phi becomes
// C y = nu y, C = L^{-1} P M P^T L^{-T}, nu = 1 / (lambda - sigma),
// phi = P^T L^{-T} y. Each Lanczos step costs one pair of triangular solves
// and one product with M, inner products are Euclidean (Spectra's
// generalized shift-invert mode would add several M products per step for
// M-inner products), and a singular M is harmless.
class ShiftInvertOperator {
 public:
  using Scalar = double;

  explicit ShiftInvertOperator(const AssembledModel& model)
      : model_(model), n_(model.K.rows()), work_(n_), product_(n_) {
    cholmod_start(&common_);
    common_.print = 0;
    common_.supernodal = CHOLMOD_SUPERNODAL;
  }
  ~ShiftInvertOperator() {
    for (cholmod_dense** d : {&x_, &y_, &e_}) {
      if (*d != nullptr) cholmod_free_dense(d, &common_);
    }
    if (factor_ != nullptr) cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }
  ShiftInvertOperator(const ShiftInvertOperator&) = delete;
  ShiftInvertOperator& operator=(const ShiftInvertOperator&) = delete;

  Eigen::Index rows() const { return n_; }
  Eigen::Index cols() const { return n_; }

  /// Factorizes K - sigma M; throws NumericalError if it is not positive definite.
  void Factorize(double sigma) {
    SparseMat a = SparseMat(model_.K - sigma * model_.M).triangularView<Eigen::Upper>();
    a.makeCompressed();
    cholmod_sparse s{};
    s.nrow = s.ncol = static_cast<size_t>(n_);
    s.nzmax = static_cast<size_t>(a.nonZeros());
    s.p = a.outerIndexPtr();
    s.i = a.innerIndexPtr();
    s.x = a.valuePtr();
    s.stype = 1;
    s.itype = CHOLMOD_INT;
    s.xtype = CHOLMOD_REAL;
    s.dtype = CHOLMOD_DOUBLE;
    s.sorted = 1;
    s.packed = 1;
    if (factor_ == nullptr) factor_ = cholmod_analyze(&s, &common_);
    if (factor_ == nullptr) throw NumericalError("CHOLMOD could not analyse K - sigma M (out of memory?)");
    const int ok = cholmod_factorize(&s, factor_, &common_);
    if (!ok || common_.status < CHOLMOD_OK) {
      throw NumericalError("CHOLMOD failed to factorize K - sigma M (status " + std::to_string(common_.status) + ")");
    }
    const std::string hint = "K - sigma M (sigma = " + std::to_string(sigma) +
                             ") is not positive definite: a mechanism without mass, or a shift inside the spectrum";
    perm_ = static_cast<const int*>(factor_->Perm);
    if (common_.status == CHOLMOD_NOT_POSDEF) {
      const int col = static_cast<int>(factor_->minor);
      const int f = perm_ != nullptr && col < n_ ? perm_[col] : col;
      throw NumericalError(hint + "; the factorization failed near " + DescribeFreeDof(model_.dofs, f));
    }
    if (!factor_->is_ll) throw NumericalError("CHOLMOD returned an LDL' factorization; LL' expected");
    // pivots at round-off level: a singular matrix that CHOLMOD did not catch
    const double rcond = cholmod_rcond(factor_, &common_);
    if (!(rcond > 10.0 * std::numeric_limits<double>::epsilon())) {
      throw NumericalError(hint + " (reciprocal condition estimate " + std::to_string(rcond) + ")");
    }
  }

  /// y = C x.
  void perform_op(const double* x_in, double* y_out) const {
    Solve(CHOLMOD_Lt, x_in);
    const double* z = static_cast<const double*>(x_->x);
    for (Eigen::Index k = 0; k < n_; ++k) work_[Perm(k)] = z[k];
    product_.noalias() = model_.M * work_;
    for (Eigen::Index k = 0; k < n_; ++k) work_[k] = product_[Perm(k)];
    Solve(CHOLMOD_L, work_.data());
    std::copy_n(static_cast<const double*>(x_->x), n_, y_out);
  }

  /// Mode shapes phi = P^T L^{-T} y from eigenvectors y of C (columns).
  Eigen::MatrixXd Recover(const Eigen::MatrixXd& y) const {
    Eigen::MatrixXd phi(n_, y.cols());
    for (Eigen::Index j = 0; j < y.cols(); ++j) {
      Solve(CHOLMOD_Lt, y.col(j).data());
      const double* z = static_cast<const double*>(x_->x);
      for (Eigen::Index k = 0; k < n_; ++k) phi(Perm(k), j) = z[k];
    }
    return phi;
  }

 private:
  Eigen::Index Perm(Eigen::Index k) const { return perm_ != nullptr ? perm_[k] : k; }

  // x_ = solution of the CHOLMOD system `sys` with right-hand side b
  void Solve(int sys, const double* b_in) const {
    cholmod_dense b{};
    b.nrow = static_cast<size_t>(n_);
    b.ncol = 1;
    b.nzmax = static_cast<size_t>(n_);
    b.d = static_cast<size_t>(n_);
    b.x = const_cast<double*>(b_in);
    b.xtype = CHOLMOD_REAL;
    b.dtype = CHOLMOD_DOUBLE;
    if (!cholmod_solve2(sys, factor_, &b, nullptr, &x_, nullptr, &y_, &e_, &common_)) {
      throw NumericalError("CHOLMOD triangular solve failed");
    }
  }

  const AssembledModel& model_;
  Eigen::Index n_;
  mutable cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  const int* perm_ = nullptr;
  mutable cholmod_dense* x_ = nullptr;
  mutable cholmod_dense* y_ = nullptr;
  mutable cholmod_dense* e_ = nullptr;
  mutable Eigen::VectorXd work_;
  mutable Eigen::VectorXd product_;
};

// default shift: a small fraction of the median diag(K)/diag(M) ratio
double AutoShift(const AssembledModel& model) {
  std::vector<double> ratio;
  ratio.reserve(model.K.rows());
  for (Eigen::Index i = 0; i < model.K.rows(); ++i) {
    const double k = model.K.coeff(i, i), m = model.M.coeff(i, i);
    if (k > 0.0 && m > 0.0) ratio.push_back(k / m);
  }
  if (ratio.empty()) {
    // no DOF with both stiffness and mass: fall back on the mass alone
    double mmax = 0.0;
    for (Eigen::Index i = 0; i < model.M.rows(); ++i) mmax = std::max(mmax, model.M.coeff(i, i));
    if (!(mmax > 0.0)) throw NumericalError("modal analysis: the model has no mass");
    return -1.0;
  }
  auto mid = ratio.begin() + ratio.size() / 2;
  std::nth_element(ratio.begin(), mid, ratio.end());
  return -1e-6 * *mid;
}

}  // namespace

ModalResult SolveModes(const AssembledModel& model, const ModalOptions& options) {
  const int n = static_cast<int>(model.K.rows());
  if (model.K.cols() != n || model.M.rows() != n || model.M.cols() != n) {
    throw InputError("modal analysis: K and M must be square and of the same size");
  }
  if (options.count < 1) throw InputError("modal analysis: the number of modes must be at least 1");
  if (options.count >= n) {
    throw InputError("modal analysis: " + std::to_string(options.count) + " modes asked, but the model has only " +
                     std::to_string(n) + " free DOF (at most " + std::to_string(n - 1) + " modes)");
  }
  if (options.shift > 0.0) throw InputError("modal analysis: the shift must be negative (or 0 for automatic)");
  if (!(options.tolerance > 0.0)) throw InputError("modal analysis: the tolerance must be positive");
  const double sigma = options.shift < 0.0 ? options.shift : AutoShift(model);

  ShiftInvertOperator op(model);
  op.Factorize(sigma);
  const int nev = options.count;
  const int ncv = std::min(n, std::max(2 * nev + 1, nev + 20));
  Spectra::SymEigsSolver<ShiftInvertOperator> eigs(op, nev, ncv);
  eigs.init();
  const int maxit = 1000;
  eigs.compute(Spectra::SortRule::LargestAlge, maxit, options.tolerance, Spectra::SortRule::LargestAlge);
  if (eigs.info() != Spectra::CompInfo::Successful) {
    throw NumericalError("modal analysis: Spectra did not converge to " + std::to_string(nev) + " modes in " +
                         std::to_string(maxit) + " restarts (shift " + std::to_string(sigma) + ")");
  }
  // nu = 1 / (lambda - sigma) > 0 for every mode with mass
  const Eigen::VectorXd nu = eigs.eigenvalues();
  if (!(nu.minCoeff() > 1e-12 * nu.maxCoeff())) {
    throw NumericalError("modal analysis: fewer than " + std::to_string(nev) +
                         " modes have mass (too many massless DOF)");
  }
  const Eigen::MatrixXd phi = op.Recover(eigs.eigenvectors());

  // Rayleigh-Ritz on the converged subspace: M-orthonormal modes, ascending
  const Eigen::MatrixXd kr = phi.transpose() * (model.K * phi);
  const Eigen::MatrixXd mr = phi.transpose() * (model.M * phi);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> rr(0.5 * (kr + kr.transpose()),
                                                               0.5 * (mr + mr.transpose()));
  if (rr.info() != Eigen::Success) throw NumericalError("modal analysis: the modes are not M-independent");
  ModalResult out;
  out.modes = phi * rr.eigenvectors();
  out.frequencies_hz.resize(nev);
  for (int k = 0; k < nev; ++k) {
    const double lambda = rr.eigenvalues()[k];
    out.frequencies_hz[k] = std::copysign(std::sqrt(std::abs(lambda)), lambda) / (2.0 * M_PI);
  }
  return out;
}

}  // namespace flexmb::fe
