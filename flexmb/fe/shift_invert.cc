#include "flexmb/fe/shift_invert.h"

#include <Eigen/Dense>
#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb::fe {

namespace {
using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
}  // namespace

ShiftInvertOperator::ShiftInvertOperator(const SparseMat& m, const SparseCholesky& factor)
    : m_(m), factor_(factor), n_(factor.rows()), work_(n_), product_(n_) {}

void ShiftInvertOperator::perform_op(const double* x_in, double* y_out) const {
  factor_.SolveLt(x_in, y_out);
  for (Eigen::Index k = 0; k < n_; ++k) work_[Perm(k)] = y_out[k];
  product_.noalias() = m_ * work_;
  for (Eigen::Index k = 0; k < n_; ++k) work_[k] = product_[Perm(k)];
  factor_.SolveL(work_.data(), y_out);
}

Eigen::MatrixXd ShiftInvertOperator::Apply(const Eigen::MatrixXd& v) const {
  const Eigen::MatrixXd y = factor_.SolveLt(v);
  // row-major blocks: one pass over M serves all columns
  RowMat z(n_, v.cols());
  for (Eigen::Index k = 0; k < n_; ++k) z.row(Perm(k)) = y.row(k);
  RowMat w(n_, v.cols());
  w.noalias() = m_ * z;
  Eigen::MatrixXd u(n_, v.cols());
  for (Eigen::Index k = 0; k < n_; ++k) u.row(k) = w.row(Perm(k));
  return factor_.SolveL(u);
}

Eigen::MatrixXd ShiftInvertOperator::Recover(const Eigen::MatrixXd& y) const {
  const Eigen::MatrixXd x = factor_.SolveLt(y);
  Eigen::MatrixXd phi(n_, y.cols());
  for (Eigen::Index k = 0; k < n_; ++k) phi.row(Perm(k)) = x.row(k);
  return phi;
}

void CheckModalRequest(const SparseMat& K, const SparseMat& M, const SparseCholesky& factor, double shift,
                       int count, double tolerance, const std::string& what) {
  const Eigen::Index n = K.rows();
  if (K.cols() != n || M.rows() != n || M.cols() != n || factor.rows() != n) {
    throw InputError(what + ": K, M and the factorization must be square and of the same size");
  }
  if (count < 1) throw InputError(what + ": the number of modes must be at least 1");
  if (count >= n) {
    throw InputError(what + ": " + std::to_string(count) + " modes asked, but the problem has only " +
                     std::to_string(n) + " DOF (at most " + std::to_string(n - 1) + " modes)");
  }
  if (shift > 0.0) throw InputError(what + ": the shift must not be positive");
  if (!(tolerance > 0.0)) throw InputError(what + ": the tolerance must be positive");
}

ModalResult RayleighRitzModes(const SparseMat& K, const SparseMat& M, const Eigen::VectorXd& nu,
                              const Eigen::MatrixXd& phi, const std::string& what) {
  const Eigen::Index count = phi.cols();
  // nu = 1 / (lambda - sigma) > 0 for every mode with mass
  if (!(nu.minCoeff() > 1e-12 * nu.maxCoeff())) {
    throw NumericalError(what + ": fewer than " + std::to_string(count) +
                         " modes have mass (too many massless DOF)");
  }
  const Eigen::MatrixXd kr = phi.transpose() * (K * phi);
  const Eigen::MatrixXd mr = phi.transpose() * (M * phi);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> rr(0.5 * (kr + kr.transpose()),
                                                               0.5 * (mr + mr.transpose()));
  if (rr.info() != Eigen::Success) throw NumericalError(what + ": the modes are not M-independent");
  ModalResult out;
  out.modes = phi * rr.eigenvectors();
  out.frequencies_hz.resize(count);
  for (Eigen::Index k = 0; k < count; ++k) {
    const double lambda = rr.eigenvalues()[k];
    out.frequencies_hz[k] = std::copysign(std::sqrt(std::abs(lambda)), lambda) / (2.0 * M_PI);
  }
  return out;
}

}  // namespace flexmb::fe
