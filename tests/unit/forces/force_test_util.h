#pragma once
// Shared checks of the force element tests: random marker states, central
// finite differences of the wrench (reference for K and C), Newton's third
// law and the potential energy gradient.

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/forces/force_element.h"
#include "flexmb/forces/rope.h"
#include "flexmb/joints/motion_driver.h"
#include "flexmb/math/rotation.h"
#include "flexmb/model_file/model_file.h"

namespace flexmb::testing {

/// Rope properties with a constant free length L0 [m]: EA [N], falls,
/// damping time beta [s].
inline RopeLaw TestRopeLaw(double EA, int falls, double beta, double L0) {
  RopeLaw law;
  law.axial_stiffness = EA;
  law.falls = falls;
  law.damping_time = beta;
  law.free_length = L0;
  return law;
}

inline Vec3 RandomVec(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return Vec3(u(rng), u(rng), u(rng));
}

/// Random pose within [-1, 1]^3, random orientation and twist.
inline MarkerState RandomMarker(std::mt19937& rng) {
  MarkerState m;
  m.p_WM = RandomVec(rng, 1.0);
  m.R_WM = ExpSO3(RandomVec(rng, 3.0));
  m.v_WM = RandomVec(rng, 2.0);
  m.w_WM = RandomVec(rng, 2.0);
  return m;
}

/// Pose variation k of marker m (flexmb::PerturbMarker), keeping its twist.
inline MarkerState Perturbed(const MarkerState& m, int k, double eps) {
  MarkerState p = PerturbMarker(m, k, eps);
  p.v_WM = m.v_WM;
  p.w_WM = m.w_WM;
  return p;
}

/// Twist component k (v then w) of marker m moved by eps.
inline MarkerState TwistPerturbed(const MarkerState& m, int k, double eps) {
  MarkerState p = m;
  if (k < 3)
    p.v_WM(k) += eps;
  else
    p.w_WM(k - 3) += eps;
  return p;
}

inline Vec12 Wrench(const ForceElement& f, const MarkerState& mi, const MarkerState& mj, double t) {
  ForceEval e;
  f.Evaluate(mi, mj, t, e);
  return e.wrench;
}

/// Central differences of the wrench with respect to the pose variations
/// (`twist` = false) or the twists (`twist` = true); `columns` = 6 for
/// single-marker elements.
inline Mat12 FiniteDifference(const ForceElement& f, const MarkerState& mi, const MarkerState& mj,
                              double t, bool twist, int columns = 12, double h = 1e-6) {
  Mat12 D = Mat12::Zero();
  for (int k = 0; k < columns; ++k) {
    const bool on_i = k < 6;
    auto move = [&](const MarkerState& m, double eps) {
      return twist ? TwistPerturbed(m, k % 6, eps) : Perturbed(m, k % 6, eps);
    };
    const MarkerState ip = on_i ? move(mi, h) : mi, im = on_i ? move(mi, -h) : mi;
    const MarkerState jp = on_i ? mj : move(mj, h), jm = on_i ? mj : move(mj, -h);
    D.col(k) = (Wrench(f, ip, jp, t) - Wrench(f, im, jm, t)) / (2 * h);
  }
  return D;
}

/// Max-norm of a - b relative to max(1, |b|_max).
inline double RelErr(const Mat12& a, const Mat12& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

/// Analytic K and C against central differences, to `tol` relative.
inline void ExpectTangents(const ForceElement& f, const MarkerState& mi, const MarkerState& mj, double t,
                           int columns = 12, double tol = 1e-6) {
  ForceEval e;
  f.Evaluate(mi, mj, t, e);
  const Mat12 Kfd = FiniteDifference(f, mi, mj, t, false, columns);
  const Mat12 Cfd = FiniteDifference(f, mi, mj, t, true, columns);
  EXPECT_LT(RelErr(e.K, Kfd), tol) << f.type() << " K analytic\n" << e.K << "\nK fd\n" << Kfd;
  EXPECT_LT(RelErr(e.C, Cfd), tol) << f.type() << " C analytic\n" << e.C << "\nC fd\n" << Cfd;
}

/// Sum of forces and of moments about an arbitrary point o vanish.
inline void ExpectThirdLaw(const ForceElement& f, const MarkerState& mi, const MarkerState& mj, double t) {
  const Vec12 w = Wrench(f, mi, mj, t);
  const Vec3 o(0.3, -0.7, 1.1);
  const Vec3 fsum = w.segment<3>(0) + w.segment<3>(6);
  const Vec3 msum = w.segment<3>(3) + w.segment<3>(9) + (mi.p_WM - o).cross(w.segment<3>(0)) +
                    (mj.p_WM - o).cross(w.segment<3>(6));
  const double scale = std::max(1.0, w.cwiseAbs().maxCoeff());
  EXPECT_LT(fsum.norm(), 1e-12 * scale) << f.type();
  EXPECT_LT(msum.norm(), 1e-11 * scale) << f.type();
  EXPECT_GT(w.cwiseAbs().maxCoeff(), 1e-3) << f.type() << ": trivial wrench";
}

/// Central difference of the potential energy: -dV/dx must equal the wrench.
inline void ExpectPotentialGradient(const ForceElement& f, const MarkerState& mi, const MarkerState& mj,
                                    double t, double tol = 1e-6) {
  const double h = 1e-6;
  Vec12 grad;
  for (int k = 0; k < 12; ++k) {
    const bool on_i = k < 6;
    const MarkerState ip = on_i ? Perturbed(mi, k, h) : mi, im = on_i ? Perturbed(mi, k, -h) : mi;
    const MarkerState jp = on_i ? mj : Perturbed(mj, k - 6, h), jm = on_i ? mj : Perturbed(mj, k - 6, -h);
    grad(k) = (f.PotentialEnergy(ip, jp, t) - f.PotentialEnergy(im, jm, t)) / (2 * h);
  }
  const Vec12 w = Wrench(f, mi, mj, t);
  EXPECT_LT((w + grad).cwiseAbs().maxCoeff(), tol * std::max(1.0, w.cwiseAbs().maxCoeff()))
      << f.type() << "\nwrench " << w.transpose() << "\n-dV/dx " << -grad.transpose();
}

/// Central differences (step h) of the wrench `eval(markers)` (6 n entries)
/// of an element on n markers, by each marker's position (Kfd) and twist
/// (Cfd) variation, as the element's K_n and C_n.
template <class Eval>
void MarkerFiniteDifferences(Eval&& eval, const std::vector<MarkerState>& ms, double h, MatX& Kfd, MatX& Cfd) {
  const int n = 6 * static_cast<int>(ms.size());
  Kfd.resize(n, n);
  Cfd.resize(n, n);
  for (int c = 0; c < n; ++c)
    for (int twist = 0; twist < 2; ++twist) {
      std::vector<MarkerState> p = ms, m = ms;
      const int mk = c / 6, k = c % 6;
      p[mk] = twist ? TwistPerturbed(ms[mk], k, h) : Perturbed(ms[mk], k, h);
      m[mk] = twist ? TwistPerturbed(ms[mk], k, -h) : Perturbed(ms[mk], k, -h);
      (twist ? Cfd : Kfd).col(c) = (eval(p) - eval(m)) / (2 * h);
    }
}

/// The message of the InputError that make() throws, or "no error".
template <class Make>
std::string InputErrorMessage(Make&& make) {
  try {
    make();
  } catch (const InputError& e) {
    return std::string(e.what());
  }
  return std::string("no error");
}

/// Expects loading the model text `text` as file `file` to throw an
/// InputError whose message starts with `prefix` (file, line, entity) and
/// contains `part`.
inline void ExpectModelError(const std::string& text, const char* file, const std::string& prefix,
                             const char* part) {
  try {
    LoadModelString(text, file);
    ADD_FAILURE() << "no error for " << text;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
    EXPECT_NE(what.find(part), std::string::npos) << what;
  }
}

/// The power [W] of the wrenches `wrench_n` (6 n) on markers moving with
/// their twists.
inline double MarkerPower(const VecX& wrench_n, const std::vector<MarkerState>& ms) {
  double power = 0.0;
  for (size_t k = 0; k < ms.size(); ++k)
    power += wrench_n.segment<3>(6 * k).dot(ms[k].v_WM) + wrench_n.segment<3>(6 * k + 3).dot(ms[k].w_WM);
  return power;
}

/// The markers moved on by their twists for the time s [s] (first order).
inline std::vector<MarkerState> MarkersMoved(const std::vector<MarkerState>& ms, double s) {
  std::vector<MarkerState> r = ms;
  for (MarkerState& m : r) {
    m.p_WM += s * m.v_WM;
    m.R_WM = ExpSO3(s * m.w_WM) * m.R_WM;
  }
  return r;
}

}  // namespace flexmb::testing
