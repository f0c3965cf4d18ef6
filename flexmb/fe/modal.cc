#include "flexmb/fe/modal.h"

#include <Spectra/SymEigsSolver.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/shift_invert.h"

namespace flexmb::fe {

std::string DescribeFreeDof(const DofMap& dofs, int f) {
  for (size_t n = 0; n < dofs.free.size(); ++n) {
    for (int c = 0; c < 6; ++c) {
      if (dofs.free[n][c] == f) {
        const std::string node = n < dofs.node_ids.size() ? "node " + std::to_string(dofs.node_ids[n])
                                                          : "node #" + std::to_string(n + 1) + " in file order";
        return "free DOF " + std::to_string(f) + " (" + node + ", " + kDofComponentNames[c] + ")";
      }
    }
  }
  return "free DOF " + std::to_string(f);
}

namespace {

// Default shift. The lowest modes are found well when sigma lies close below
// them: nu = 1 / (lambda - sigma) separates the rigid modes (lambda = 0) from
// the first flexible ones only if |sigma| is not much larger than those.
// A fraction of a typical element frequency (median diag(K)/diag(M)) is
// far above the first frequencies of slender models (a beam of thousands of
// elements loses rigid modes), so the start is the smaller of that and
// (2 pi * 1 Hz)^2: frequencies of machine parts are above ~1 Hz, and any
// positive frequency keeps the order. Time is in seconds in every unit system.
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
  const double one_hz = std::pow(2.0 * M_PI, 2);
  return -std::min(one_hz, 1e-6 * *mid);
}

// Factorizes K - sigma M; when the shift is automatic and the factor is not
// positive definite or is near-singular (round-off of K's rigid-body null
// space exceeding |sigma| M), retries with a 100 times larger |sigma|.
double FactorizeShifted(const AssembledModel& model, double sigma, bool automatic, SparseCholesky& factor) {
  const int attempts = automatic ? 4 : 1;
  for (int attempt = 1;; ++attempt, sigma *= 100.0) {
    const std::string name = "modal analysis: K - sigma M (sigma = " + std::to_string(sigma) + ")";
    try {
      factor.Factorize(SparseMat(model.K - sigma * model.M), name,
                       [&](int f) { return DescribeFreeDof(model.dofs, f); });
    } catch (const NumericalError&) {
      if (attempt < attempts) continue;
      throw;
    }
    // pivots at round-off level: a singular matrix that CHOLMOD did not catch
    const double rcond = factor.RcondEstimate();
    if (rcond > 10.0 * std::numeric_limits<double>::epsilon()) return sigma;
    if (attempt >= attempts) {
      throw NumericalError(name + " is singular to working precision (reciprocal condition estimate " +
                           std::to_string(rcond) + ")");
    }
  }
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
  SparseCholesky factor;
  const bool automatic = options.shift == 0.0;
  const double sigma = FactorizeShifted(model, automatic ? AutoShift(model) : options.shift, automatic, factor);
  return SolveModesFactorized(model.K, model.M, factor, sigma, options.count, options.tolerance);
}

ModalResult SolveModesFactorized(const SparseMat& K, const SparseMat& M, const SparseCholesky& factor, double shift,
                                 int count, double tolerance, const std::string& what) {
  CheckModalRequest(K, M, factor, shift, count, tolerance, what);
  const int n = static_cast<int>(K.rows());
  ShiftInvertOperator op(M, factor);
  const int ncv = std::min(n, std::max(2 * count + 1, count + 20));
  Spectra::SymEigsSolver<ShiftInvertOperator> eigs(op, count, ncv);
  eigs.init();
  const int maxit = 1000;
  eigs.compute(Spectra::SortRule::LargestAlge, maxit, tolerance, Spectra::SortRule::LargestAlge);
  if (eigs.info() != Spectra::CompInfo::Successful) {
    throw NumericalError(what + ": Spectra did not converge to " + std::to_string(count) + " modes in " +
                         std::to_string(maxit) + " restarts (shift " + std::to_string(shift) + ")");
  }
  return RayleighRitzModes(K, M, eigs.eigenvalues(), op.Recover(eigs.eigenvectors()), what);
}

}  // namespace flexmb::fe
