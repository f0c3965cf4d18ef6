#include "flexmb/solver/system_modes.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "flexmb/common/error.h"

namespace flexmb {
namespace {

constexpr double kModesTwoPi = 2.0 * std::numbers::pi;

using ModesCVec = Eigen::VectorXcd;

// mode shape N z scaled to a largest entry of 1 (real)
void ModesSetShape(const MatX& N, const ModesCVec& z, SystemMode& mode) {
  const ModesCVec x = N.cast<std::complex<double>>() * z;
  Eigen::Index k = 0;
  x.cwiseAbs().maxCoeff(&k);
  const ModesCVec y = std::abs(x(k)) > 0.0 ? ModesCVec(x / x(k)) : x;
  mode.shape = y.real();
  mode.shape_imag = y.imag();
}

void ModesSetEigenvalue(std::complex<double> s, SystemMode& mode) {
  mode.eigenvalue = s;
  const double r = std::abs(s);
  mode.frequency_hz = r / kModesTwoPi;
  mode.damped_frequency_hz = std::abs(s.imag()) / kModesTwoPi;
  mode.damping_ratio = r > 0.0 ? 0.0 - s.real() / r : 0.0;  // never -0
}

}  // namespace

const char* ModeKindName(ModeKind kind) {
  switch (kind) {
    case ModeKind::kRigid: return "rigid";
    case ModeKind::kOscillatory: return "oscillatory";
    case ModeKind::kOverdamped: return "overdamped";
    default: return "unstable";
  }
}

std::vector<SystemMode> SolveSystemModes(const LinearizedSystem& sys, double zero_tol) {
  const int n = static_cast<int>(sys.Mr.rows());
  std::vector<SystemMode> modes;
  if (n == 0) return modes;
  // mass-normalized stiffness Kt = L^-1 Kr L^-T
  const Eigen::LLT<MatX> llt(sys.Mr);
  if (llt.info() != Eigen::Success) throw NumericalError("system modes: the reduced mass matrix is not positive definite");
  const MatX Lm = llt.matrixL();
  MatX Kt = Lm.triangularView<Eigen::Lower>().solve(sys.Kr);
  Kt = Lm.triangularView<Eigen::Lower>().solve(Kt.transpose()).transpose().eval();
  const double kscale = Kt.cwiseAbs().maxCoeff();
  const MatX Ks = 0.5 * (Kt + Kt.transpose());
  const Eigen::SelfAdjointEigenSolver<MatX> sym(Ks);
  if (sym.info() != Eigen::Success) throw NumericalError("system modes: the symmetric eigensolver failed");
  const VecX w2 = sym.eigenvalues();
  const double w2max = std::max(w2.cwiseAbs().maxCoeff(), 0.0);
  const double tol = zero_tol * w2max;
  const MatX Lt_inv_U = Lm.transpose().triangularView<Eigen::Upper>().solve(sym.eigenvectors());
  // rigid modes: the null space of the (symmetric part of the) stiffness
  int rigid = 0;
  for (int k = 0; k < n; ++k) {
    if (std::abs(w2(k)) > tol && w2max > 0.0) continue;
    SystemMode mode;
    mode.kind = ModeKind::kRigid;
    ModesSetShape(sys.N, Lt_inv_U.col(k).cast<std::complex<double>>(), mode);
    modes.push_back(mode);
    ++rigid;
  }
  const double cscale = sys.Cr.cwiseAbs().maxCoeff();
  const double asym = (Kt - Kt.transpose()).cwiseAbs().maxCoeff();
  const bool undamped = cscale == 0.0 && asym <= 1e-12 * std::max(kscale, 1e-300);
  if (undamped) {
    for (int k = 0; k < n; ++k) {
      if (!(std::abs(w2(k)) > tol && w2max > 0.0)) continue;
      SystemMode mode;
      const double w = std::sqrt(std::abs(w2(k)));
      mode.kind = w2(k) > 0.0 ? ModeKind::kOscillatory : ModeKind::kUnstable;
      ModesSetEigenvalue(w2(k) > 0.0 ? std::complex<double>(0.0, w) : std::complex<double>(w, 0.0), mode);
      ModesSetShape(sys.N, Lt_inv_U.col(k).cast<std::complex<double>>(), mode);
      modes.push_back(mode);
    }
  } else {
    // first-order form in y = L^T z: [[0, I], [-Kt, -Ct]]
    MatX Ct = Lm.triangularView<Eigen::Lower>().solve(sys.Cr);
    Ct = Lm.triangularView<Eigen::Lower>().solve(Ct.transpose()).transpose().eval();
    MatX A = MatX::Zero(2 * n, 2 * n);
    A.topRightCorner(n, n).setIdentity();
    A.bottomLeftCorner(n, n) = -Kt;
    A.bottomRightCorner(n, n) = -Ct;
    const Eigen::EigenSolver<MatX> es(A);
    if (es.info() != Eigen::Success) throw NumericalError("system modes: the eigensolver failed");
    const ModesCVec s = es.eigenvalues();
    const double smax = s.cwiseAbs().maxCoeff();
    // the rigid modes' eigenvalues (2 per rigid mode, or 1 with damping): the
    // 2 rigid smallest magnitudes below the tolerance are dropped
    std::vector<int> order(2 * n);
    for (int k = 0; k < 2 * n; ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&s](int a, int b) { return std::abs(s(a)) < std::abs(s(b)); });
    const double stol = std::sqrt(zero_tol) * smax;
    const Eigen::MatrixXcd Ltc = Lm.transpose().cast<std::complex<double>>();
    int dropped = 0;
    for (int idx : order) {
      const std::complex<double> sk = s(idx);
      if (dropped < 2 * rigid && std::abs(sk) <= stol) {
        ++dropped;
        continue;
      }
      const bool real = std::abs(sk.imag()) <= 1e-12 * smax;
      if (!real && sk.imag() < 0.0) continue;
      SystemMode mode;
      mode.kind = sk.real() > 1e-12 * smax ? ModeKind::kUnstable
                  : real                   ? ModeKind::kOverdamped
                                           : ModeKind::kOscillatory;
      ModesSetEigenvalue(real ? std::complex<double>(sk.real(), 0.0) : sk, mode);
      const ModesCVec y = es.eigenvectors().col(idx).head(n);
      const ModesCVec z = Ltc.triangularView<Eigen::Upper>().solve(y);
      ModesSetShape(sys.N, z, mode);
      modes.push_back(mode);
    }
  }
  std::stable_sort(modes.begin(), modes.end(), [](const SystemMode& a, const SystemMode& b) {
    if ((a.kind == ModeKind::kRigid) != (b.kind == ModeKind::kRigid)) return a.kind == ModeKind::kRigid;
    return a.frequency_hz < b.frequency_hz;
  });
  for (const SystemMode& m : modes)
    if (!m.shape.allFinite() || !std::isfinite(m.frequency_hz))
      throw NumericalError("system modes: a mode is not finite (ill-conditioned mass or stiffness)");
  return modes;
}

}  // namespace flexmb
