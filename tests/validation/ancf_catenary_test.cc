// Validation of the planar ANCF beam as a cable: a cable pinned at two
// points at the same height hangs under gravity; its nodes must lie on the
// analytic elastic catenary (Irvine 1981, Cable Structures, eq. 2.8; see
// docs/validation.md "ANCF beams"), found here by bisection on the
// horizontal tension H.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "flexmb/ancf/ancf_statics.h"

namespace flexmb::ancf {
namespace {

// elastic catenary: unstretched length L0, weight w [N/m of unstretched
// length], axial stiffness EA, supports a span S apart at equal height; s is
// the unstretched arc length from the left support, z upward
struct Catenary {
  double L0, w, EA, S, H = 0.0, V = 0.0;
  double X(double s) const {
    return H * s / EA + H / w * (std::asinh(V / H) - std::asinh((V - w * s) / H));
  }
  double Z(double s) const {
    return -(V * s - 0.5 * w * s * s) / EA -
           H / w * (std::hypot(1.0, V / H) - std::hypot(1.0, (V - w * s) / H));
  }
  void Solve() {
    V = 0.5 * w * L0;
    double lo = 1e-9 * w * L0, hi = 1e3 * w * L0;
    for (int it = 0; it < 200; ++it) {
      H = 0.5 * (lo + hi);
      (X(L0) > S ? hi : lo) = H;
    }
  }
};

TEST(AncfCatenary, HangingCableMatchesElasticCatenary) {
  const double L0 = 12.0, S = 10.0, g = 9.81;
  AncfBeam2dData d;
  d.length = L0;
  d.elements = 24;
  d.section.E = 1.0e8;
  d.section.A = 1.0e-4;
  // a cable: bending stiffness negligible against the tension (boundary
  // layer sqrt(EI / H) ~ 1 mm at the supports)
  d.section.I = 1.0e-13;
  d.section.rho = 8000.0;
  d.normal_W = Vec3(0.0, -1.0, 0.0);  // plane x-z: axes u = x, w = z
  const AncfBeam2dBody cable("cable", d);
  Catenary c{L0, d.section.rho * d.section.A * g, d.section.E * d.section.A, S};
  c.Solve();
  // start from a parabola through the supports with the sag of an
  // inextensible cable of length L0, nodes at equal arc length, unit slopes
  const int n = d.elements;
  VecX q(cable.nq()), v(cable.nv());
  const double sag = std::sqrt(3.0 * S * (L0 - S) / 8.0);
  auto z = [&](double x) { return -4.0 * sag * x * (S - x) / (S * S); };
  const int fine = 20000;
  std::vector<double> arc(fine + 1, 0.0);
  for (int i = 1; i <= fine; ++i)
    arc[i] = arc[i - 1] + std::hypot(S / fine, z(S * i / fine) - z(S * (i - 1) / fine));
  for (int k = 0, i = 0; k <= n; ++k) {
    const double target = arc[fine] * k / n;
    while (i < fine && arc[i + 1] < target) ++i;
    const double x = S * std::min(1.0, (i + (target - arc[i]) / (arc[std::min(i + 1, fine)] - arc[i] + 1e-300)) / fine);
    const double dz = -4.0 * sag * (S - 2.0 * x) / (S * S);
    const double c = 1.0 / std::hypot(1.0, dz);
    q.segment<4>(4 * k) << x, z(x), c, dz * c;
  }
  AncfStaticsSettings s;
  s.load_steps = 1;
  SolveAncfStatics(cable, {0, 1, 4 * n, 4 * n + 1}, VecX::Zero(cable.nv()), Vec3(0, 0, -g), q, s);
  double err = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double sk = L0 * k / n;
    err = std::max(err, std::hypot(q(4 * k) - c.X(sk), q(4 * k + 1) - c.Z(sk)));
  }
  // nodes on the catenary (sag 2.97 m) to 1e-6 of the span (measured 5e-8)
  EXPECT_LT(err, 1e-6 * S);
  EXPECT_NEAR(q(4 * (n / 2) + 1), c.Z(0.5 * L0), 1e-6 * S);
  // tension T = EA eps against sqrt(H^2 + (V - w s)^2) at the axial
  // quadrature points (where the reduced-integrated strain is sampled) of
  // every element
  double terr = 0.0;
  const double h = L0 / n, g1 = 0.5 - 0.5 / std::sqrt(3.0), g2 = 0.5 + 0.5 / std::sqrt(3.0);
  for (int e = 0; e < n; ++e) {
    for (double xi : {g1, g2}) {
      const double eps = cable.element().AxialStrain(q.segment<8>(4 * e), xi);
      const double sk = (e + xi) * h;
      terr = std::max(terr, std::abs(eps * c.EA - std::hypot(c.H, c.V - c.w * sk)) / c.H);
    }
  }
  EXPECT_LT(terr, 1e-6);  // measured 4e-8
}

}  // namespace
}  // namespace flexmb::ancf
