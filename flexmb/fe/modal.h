#pragma once
/// \file modal.h
/// Natural frequencies and modes of an assembled FE model: K phi = w^2 M phi
/// by shift-and-invert Lanczos (Spectra) with a supernodal CHOLMOD
/// factorization P (K - sigma M) P^T = L L^T, in the symmetric form
/// L^{-1} P M P^T L^{-T} y = y / (w^2 - sigma); sigma < 0 so free-free models
/// work. The Ritz vectors are finally refined by a Rayleigh-Ritz step on K, M.

#include <Eigen/Core>
#include <string>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/sparse_cholesky.h"

namespace flexmb::fe {

/// Options of the eigen solve.
struct ModalOptions {
  int count = 10;          ///< number of modes
  /// sigma [rad^2/s^2], < 0; 0 = automatic: -min((2 pi * 1 Hz)^2, 1e-6 *
  /// median over the free DOF of K_ii / M_ii), close below the lowest modes
  /// so that they are well separated in the transformed spectrum (also for
  /// slender models of thousands of elements), made 100 times larger (up to
  /// three times) if K - sigma M of a free-free model does not factorize.
  double shift = 0.0;
  double tolerance = 1e-10;
};

/// Result: ascending frequencies [Hz] and M-orthonormal modes (free DOF).
/// A (round-off) negative eigenvalue lambda gives the negative frequency
/// -sqrt(-lambda) / (2 pi), so that it is visible.
struct ModalResult {
  Eigen::VectorXd frequencies_hz;
  Eigen::MatrixXd modes;   ///< n_free x count
};

/// Names free DOF f of `dofs` by its node id and component for messages:
/// "free DOF 12 (node 7, rz)".
std::string DescribeFreeDof(const DofMap& dofs, int f);

/// Lowest `count` modes. Throws NumericalError if K - sigma M is not
/// positive definite (e.g. a mechanism with zero mass) or Spectra does not
/// converge; InputError if more modes are asked than DOF exist.
ModalResult SolveModes(const AssembledModel& model, const ModalOptions& options);

/// Lowest `count` modes of K phi = lambda M phi (K, M symmetric, n x n)
/// from an existing factorization `factor` of K - shift M (shift <= 0; 0
/// when K itself is positive definite, e.g. the interior stiffness K_ii of a
/// Craig-Bampton reduction, whose factor also gives the static modes).
/// Same algorithm, result and errors as SolveModes; `what` names the
/// problem in messages.
ModalResult SolveModesFactorized(const SparseMat& K, const SparseMat& M, const SparseCholesky& factor, double shift,
                                 int count, double tolerance = 1e-10, const std::string& what = "modal analysis");

}  // namespace flexmb::fe
