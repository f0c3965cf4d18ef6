// Validation of the planar ANCF beam and of the 3D ANCF cable body as
// cables: a cable pinned at two points at the same height hangs under
// gravity; its nodes must lie on the analytic elastic catenary (Irvine 1981,
// Cable Structures, eq. 2.8; see docs/validation.md "ANCF beams"), found
// here by bisection on the horizontal tension H. The 3D cable hangs in a
// plane not aligned with the world axes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "flexmb/ancf/ancf_statics.h"

namespace flexmb::ancf {
namespace ancf_catenary_test {

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

// start: a parabola through the supports with the sag of an inextensible
// cable of length L0, nodes k = 0..n at equal arc length; returns the
// horizontal position x, height z and unit slope (cx, cz) of each node
std::vector<Eigen::Vector4d> ParabolaStart(double L0, double S, int n) {
  const double sag = std::sqrt(3.0 * S * (L0 - S) / 8.0);
  auto z = [&](double x) { return -4.0 * sag * x * (S - x) / (S * S); };
  const int fine = 20000;
  std::vector<double> arc(fine + 1, 0.0);
  for (int i = 1; i <= fine; ++i)
    arc[i] = arc[i - 1] + std::hypot(S / fine, z(S * i / fine) - z(S * (i - 1) / fine));
  std::vector<Eigen::Vector4d> out;
  for (int k = 0, i = 0; k <= n; ++k) {
    const double target = arc[fine] * k / n;
    while (i < fine && arc[i + 1] < target) ++i;
    const double x = S * std::min(1.0, (i + (target - arc[i]) / (arc[std::min(i + 1, fine)] - arc[i] + 1e-300)) / fine);
    const double dz = -4.0 * sag * (S - 2.0 * x) / (S * S);
    const double c = 1.0 / std::hypot(1.0, dz);
    out.emplace_back(x, z(x), c, dz * c);
  }
  return out;
}

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
  const int n = d.elements;
  VecX q(cable.nq());
  const std::vector<Eigen::Vector4d> start = ParabolaStart(L0, S, n);
  for (int k = 0; k <= n; ++k) q.segment<4>(4 * k) = start[k];
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

TEST(AncfCatenary, Cable3dHangsOnTheCatenaryInASkewPlane) {
  // the same cable as a 3D ANCF cable body: span along u, gravity along
  // -w, with u and w not aligned with the world axes
  const double L0 = 12.0, S = 10.0, g = 9.81;
  const Vec3 u = Vec3(2.0, 1.0, 0.5).normalized();
  const Vec3 up = (Vec3(0.3, -0.4, 1.0) - u * u.dot(Vec3(0.3, -0.4, 1.0))).normalized();
  const Vec3 p0(1.0, -2.0, 0.5);
  AncfCable3dData d;
  d.length = L0;
  d.elements = 24;
  d.section.E = 1.0e8;
  d.section.A = 1.0e-4;
  d.section.I = 1.0e-13;
  d.section.rho = 8000.0;
  d.start_W = p0;
  d.direction_W = u;
  const AncfCable3dBody cable("cable", d);
  Catenary c{L0, d.section.rho * d.section.A * g, d.section.E * d.section.A, S};
  c.Solve();
  const int n = d.elements;
  VecX q(cable.nq());
  const std::vector<Eigen::Vector4d> start = ParabolaStart(L0, S, n);
  for (int k = 0; k <= n; ++k) {
    q.segment<3>(6 * k) = p0 + start[k](0) * u + start[k](1) * up;
    q.segment<3>(6 * k + 3) = start[k](2) * u + start[k](3) * up;
  }
  AncfStaticsSettings s;
  s.load_steps = 1;
  SolveAncfStatics(cable, {0, 1, 2, 6 * n, 6 * n + 1, 6 * n + 2}, VecX::Zero(cable.nv()), -g * up, q, s);
  double err = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double sk = L0 * k / n;
    const Vec3 ref = p0 + c.X(sk) * u + c.Z(sk) * up;
    err = std::max(err, (q.segment<3>(6 * k) - ref).norm());
  }
  std::printf("3D catenary: largest node distance from the catenary %.3e m\n", err);
  EXPECT_LT(err, 1e-6 * S);
  // the tension at the axial quadrature points
  double terr = 0.0;
  const double h = L0 / n, g1 = 0.5 - 0.5 / std::sqrt(3.0), g2 = 0.5 + 0.5 / std::sqrt(3.0);
  for (int e = 0; e < n; ++e) {
    for (double xi : {g1, g2}) {
      const double eps = cable.element().AxialStrain(q.segment<12>(6 * e), xi);
      terr = std::max(terr, std::abs(eps * c.EA - std::hypot(c.H, c.V - c.w * (e + xi) * h)) / c.H);
    }
  }
  EXPECT_LT(terr, 1e-6);
}

}  // namespace ancf_catenary_test
}  // namespace flexmb::ancf
