#pragma once
/// \file system_modes.h
/// Eigenvalues and mode shapes of a linearized system (linearization.h):
///   (s^2 Mr + s Cr + Kr) z = 0.
/// Without damping and with a symmetric Kr, the generalized symmetric
/// problem Kr z = w^2 Mr z (Cholesky of Mr, symmetric eigensolver: the
/// frequencies to rounding); otherwise the first-order form
///   [[0, I], [-Mr^-1 Kr, -Mr^-1 Cr]] (z, s z) = s (z, s z)
/// by the real Schur form (Eigen::EigenSolver), one mode per complex pair.
/// Rigid-body modes are the null space of Kr (eigenvalues w^2 with
/// |w^2| <= zero_tol * max |w^2|, also used to classify the first-order
/// eigenvalues) and are reported once each, with frequency 0.

#include <complex>
#include <string>
#include <vector>

#include "flexmb/solver/linearization.h"

namespace flexmb {

/// What kind of motion a mode is.
enum class ModeKind {
  kRigid,        ///< zero eigenvalue: a rigid-body (mechanism) motion without stiffness
  kOscillatory,  ///< complex pair (or undamped w^2 > 0): a vibration
  kOverdamped,   ///< real negative eigenvalue: a decaying motion without oscillation
  kUnstable,     ///< eigenvalue with positive real part (or w^2 < 0): divergence or flutter
};

/// "rigid", "oscillatory", "overdamped" or "unstable".
const char* ModeKindName(ModeKind kind);

/// One mode of the linearized system.
struct SystemMode {
  ModeKind kind = ModeKind::kOscillatory;
  std::complex<double> eigenvalue;  ///< s [1/s] (Im >= 0 for the reported one of a pair)
  double frequency_hz = 0.0;        ///< undamped natural frequency |s| / (2 pi) [Hz]
  double damped_frequency_hz = 0.0; ///< Im(s) / (2 pi) [Hz]
  double damping_ratio = 0.0;       ///< -Re(s) / |s| (0 for rigid modes)
  /// Shape in the velocity coordinates (nv): dx = Re + i Im of N z, scaled
  /// so that its largest entry is 1 (real).
  VecX shape, shape_imag;
};

/// All modes of `sys`, rigid modes first, then by frequency.
std::vector<SystemMode> SolveSystemModes(const LinearizedSystem& sys, double zero_tol = 1e-8);

}  // namespace flexmb
