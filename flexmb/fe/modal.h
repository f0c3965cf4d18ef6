#pragma once
/// \file modal.h
/// Natural frequencies and modes of an assembled FE model: K phi = w^2 M phi
/// by shift-and-invert Lanczos (Spectra) with a supernodal CHOLMOD
/// factorization P (K - sigma M) P^T = L L^T, in the symmetric form
/// L^{-1} P M P^T L^{-T} y = y / (w^2 - sigma); sigma < 0 so free-free models
/// work. The Ritz vectors are finally refined by a Rayleigh-Ritz step on K, M.

#include <Eigen/Core>

#include "flexmb/fe/assembly.h"

namespace flexmb::fe {

/// Options of the eigen solve.
struct ModalOptions {
  int count = 10;          ///< number of modes
  /// sigma [rad^2/s^2], < 0; 0 = automatic: -1e-6 times the median over the
  /// free DOF of K_ii / M_ii (a typical element frequency squared), small
  /// enough that the lowest modes are well separated in the transformed
  /// spectrum, large enough that K - sigma M of a free-free model factorizes.
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

/// Lowest `count` modes. Throws NumericalError if K - sigma M is not
/// positive definite (e.g. a mechanism with zero mass) or Spectra does not
/// converge; InputError if more modes are asked than DOF exist.
ModalResult SolveModes(const AssembledModel& model, const ModalOptions& options);

}  // namespace flexmb::fe
