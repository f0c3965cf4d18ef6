#pragma once
/// \file fe_beam_theory.h
/// Reference natural frequencies of uniform beams for the FE validation
/// tests, computed here independently of flexmb: the roots of the
/// frequency equation of a Timoshenko beam (shear flexibility and rotary
/// inertia; Timoshenko 1921, in the form of Huang 1961), which reduces to
/// the Rayleigh and Euler-Bernoulli beams when the shear compliance and then
/// the rotary inertia are set to zero. The Euler-Bernoulli eigenvalues
/// beta_n L of Blevins (1979, table 8-1) check the solver in that limit.
/// Sources: docs/validation.md, "FE: beams and solids".

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

namespace flexmb::fe::validation {

/// Euler-Bernoulli beta_n L (omega_n = (beta_n L)^2 sqrt(E I / (rho A L^4))),
/// Blevins, Formulas for Natural Frequency and Mode Shape (1979), table 8-1.
inline constexpr double kCantileverBetaL[3] = {1.87510407, 4.69409113, 7.85475744};
inline constexpr double kFreeFreeBetaL[3] = {4.73004074, 7.85320462, 10.9956078};

/// A uniform beam bending in one plane.
struct BeamProperties {
  double EI = 0.0;                ///< bending stiffness [N m^2]
  double shear_compliance = 0.0;  ///< 1 / (k G A) [1/N]; 0 = rigid in shear
  double rhoA = 0.0;              ///< mass per length [kg/m]
  double rhoI = 0.0;              ///< rotary inertia per length [kg m]; 0 = none
  double L = 0.0;                 ///< length [m]
};

/// Supports of the two ends.
enum class BeamSupport { kCantilever, kFreeFree, kPinnedPinned };

/// Determinant of the 4 x 4 boundary-condition matrix of the Timoshenko
/// beam at circular frequency omega (below the second spectrum, rho I
/// omega^2 < k G A). With w the deflection and psi the section rotation,
///   k G A (w'' - psi') + rho A omega^2 w = 0,
///   E I psi'' + k G A (w' - psi) + rho I omega^2 psi = 0,
/// w = C1 cosh(a x) + C2 sinh(a x) + C3 cos(b x) + C4 sin(b x) with a^2,
/// -b^2 the roots of E I s^4 + omega^2 (rho I + E I rho A c) s^2
/// + rho A omega^2 (rho I omega^2 c - 1) = 0 (c the shear compliance); then
/// psi = fa (C1 sinh + C2 cosh) + fb (-C3 sin + C4 cos), fa = a + g / a,
/// fb = b - g / b, g = rho A omega^2 c, and the shear force
/// V = k G A (w' - psi) = -rho A omega^2 [(C1 sinh + C2 cosh) / a
/// + (C3 sin - C4 cos) / b]. Clamped: w = psi = 0; free: psi' = V = 0;
/// pinned: w = psi' = 0.
inline double TimoshenkoDeterminant(const BeamProperties& p, BeamSupport support, double omega) {
  const double w2 = omega * omega;
  const double c = p.shear_compliance;
  const double qa = p.EI, qb = w2 * (p.rhoI + p.EI * p.rhoA * c),
               qc = p.rhoA * w2 * (p.rhoI * w2 * c - 1.0);
  const double disc = std::sqrt(qb * qb - 4.0 * qa * qc);
  const double a = std::sqrt((-qb + disc) / (2.0 * qa));
  const double b = std::sqrt((qb + disc) / (2.0 * qa));
  const double g = p.rhoA * w2 * c;
  const double fa = a + g / a, fb = b - g / b;
  // rows at x: w, psi, psi', V / (rho A omega^2), over C1..C4
  auto rows = [&](double x, Eigen::Matrix4d& r) {
    const double ch = std::cosh(a * x), sh = std::sinh(a * x), co = std::cos(b * x),
                 si = std::sin(b * x);
    r.row(0) << ch, sh, co, si;
    r.row(1) << fa * sh, fa * ch, -fb * si, fb * co;
    r.row(2) << fa * a * ch, fa * a * sh, -fb * b * co, -fb * b * si;
    r.row(3) << -sh / a, -ch / a, -si / b, co / b;
  };
  Eigen::Matrix4d r0, r1, bc;
  rows(0.0, r0);
  rows(p.L, r1);
  switch (support) {
    case BeamSupport::kCantilever:
      bc << r0.row(0), r0.row(1), r1.row(2), r1.row(3);
      break;
    case BeamSupport::kFreeFree:
      bc << r0.row(2), r0.row(3), r1.row(2), r1.row(3);
      break;
    case BeamSupport::kPinnedPinned:
      bc << r0.row(0), r0.row(2), r1.row(0), r1.row(2);
      break;
  }
  // scale the columns of the growing hyperbolic functions to keep the
  // determinant's sign and magnitude well defined
  const double s = std::cosh(a * p.L);
  bc.col(0) /= s;
  bc.col(1) /= s;
  return bc.determinant();
}

/// The n-th (1-based) flexible natural frequency omega [rad/s] of the beam:
/// a scan for sign changes of the determinant from a small fraction of the
/// Euler-Bernoulli fundamental upward, then bisection to round-off.
inline double TimoshenkoOmega(const BeamProperties& p, BeamSupport support, int n) {
  const double beta1 = support == BeamSupport::kCantilever ? kCantileverBetaL[0]
                       : support == BeamSupport::kFreeFree ? kFreeFreeBetaL[0]
                                                           : M_PI;
  const double w_eb1 = beta1 * beta1 * std::sqrt(p.EI / (p.rhoA * std::pow(p.L, 4)));
  double lo = 1e-3 * w_eb1;
  double f_lo = TimoshenkoDeterminant(p, support, lo);
  int found = 0;
  for (int step = 0; step < 200000; ++step) {
    const double hi = lo * 1.001;
    if (p.rhoI * hi * hi * p.shear_compliance >= 1.0) break;  // second spectrum
    const double f_hi = TimoshenkoDeterminant(p, support, hi);
    if ((f_lo < 0.0) != (f_hi < 0.0) && ++found == n) {
      double l = lo, h = hi, fl = f_lo;
      for (int it = 0; it < 200 && h - l > 1e-15 * h; ++it) {
        const double mid = 0.5 * (l + h);
        const double fm = TimoshenkoDeterminant(p, support, mid);
        if ((fm < 0.0) == (fl < 0.0)) {
          l = mid;
          fl = fm;
        } else {
          h = mid;
        }
      }
      return 0.5 * (l + h);
    }
    lo = hi;
    f_lo = f_hi;
  }
  throw std::runtime_error("TimoshenkoOmega: root not found");
}

/// Flexural circular frequency [rad/s] of a Timoshenko beam in a
/// sinusoidal mode of wavenumber k [1/m] (Timoshenko 1921): omega^2 is the
/// smaller root of rho A rho I c omega^4 - (rho A + k^2 (rho I + E I rho A c))
/// omega^2 + E I k^4 = 0, c the shear compliance. With the plate's D, rho t,
/// rho t^3 / 12 and 1 / (kappa G t) per unit width it is also the exact
/// frequency of a simply supported (hard support) Mindlin plate in the mode
/// sin(m pi x / a) sin(n pi y / b), k^2 = (m pi / a)^2 + (n pi / b)^2
/// (Mindlin 1951).
inline double FlexuralOmega(const BeamProperties& p, double k) {
  const double k2 = k * k;
  const double qa = p.rhoA * p.rhoI * p.shear_compliance;
  const double qb = p.rhoA + k2 * (p.rhoI + p.EI * p.rhoA * p.shear_compliance);
  const double qc = p.EI * k2 * k2;
  // smaller root, written without cancellation (also for qa = 0)
  return std::sqrt(2.0 * qc / (qb + std::sqrt(qb * qb - 4.0 * qa * qc)));
}

/// Closed form of the pinned-pinned Timoshenko beam, mode n: FlexuralOmega
/// with k = n pi / L. Checks TimoshenkoDeterminant.
inline double PinnedPinnedOmega(const BeamProperties& p, int n) {
  return FlexuralOmega(p, n * M_PI / p.L);
}

}  // namespace flexmb::fe::validation
