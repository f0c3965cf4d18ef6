// Inertia invariants of a reduced body against the Euler-Bernoulli
// cantilever (THEORY section 4): a uniform beam clamped at x = 0, reduced by
// Craig-Bampton with its tip as interface, compared with the analytic
// clamped-free mode shapes phi_i (Blevins, Formulas for Natural Frequency
// and Mode Shape, Table 8-1) integrated by quadrature: the modal momentum
// int mu phi, the effective modal masses (published fractions 0.6131,
// 0.1883, 0.0647, 0.0331 of the mass), the modal angular momentum and the
// first-order change of the inertia tensor int mu x phi, and the quadratic
// term of the inertia tensor; the rigid blocks against m, S and J of the
// uniform beam. docs/validation.md, "Reduction: inertia invariants".

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "flexmb/fe/fe_model.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/reduction/inertia_invariants.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::reduction {
namespace reduction_invariants_test {

using fe::testing::AddBeam;
using fe::testing::AddMaterial;
using fe::testing::AddNode;

constexpr double kLength = 1.0;      // [m]
constexpr double kE = 2.1e11;        // [Pa]
constexpr double kRho = 1.0;         // [kg/m^3]: rotary inertia negligible against the line mass
constexpr double kArea = 1e-4;       // [m^2]
constexpr double kIy = 1e-9, kIz = 4e-9;  // [m^4]: bending along z (Iy) well below bending along y
constexpr double kNsm = 1.0;         // [kg/m]
constexpr double kMu = kNsm + kRho * kArea;   // line mass [kg/m]

// the clamped-free mode i (1-based) of the Euler-Bernoulli beam on [0, L]:
// beta_i L from cos cosh = -1, phi = cosh - cos - sigma (sinh - sin)
struct CantileverMode {
  double beta = 0.0, sigma = 0.0;
  double Phi(double x) const {
    const double b = beta * x;
    return std::cosh(b) - std::cos(b) - sigma * (std::sinh(b) - std::sin(b));
  }
};
CantileverMode Mode(int i) {
  // the root lies within 0.2 of (i - 1/2) pi; bisection
  double lo = (i - 0.5) * M_PI - 0.5, hi = (i - 0.5) * M_PI + 0.5;
  auto f = [](double x) { return std::cos(x) * std::cosh(x) + 1.0; };
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if ((f(lo) < 0.0) == (f(mid) < 0.0)) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  CantileverMode m;
  const double bl = 0.5 * (lo + hi);
  m.beta = bl / kLength;
  m.sigma = (std::sinh(bl) - std::sin(bl)) / (std::cosh(bl) + std::cos(bl));
  return m;
}

// int_0^L g(x) dx, composite 5-point Gauss-Legendre on 400 intervals
template <class G>
double Integrate(G&& g) {
  const double xg[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  const double wg[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                        0.2369268850561891};
  const int n = 400;
  const double h = kLength / n;
  double s = 0.0;
  for (int k = 0; k < n; ++k) {
    for (int q = 0; q < 5; ++q) s += 0.5 * h * wg[q] * g((k + 0.5) * h + 0.5 * h * xg[q]);
  }
  return s;
}

struct Cantilever {
  fe::FeModel model;
  ReductionOptions options;
  int tip = -1;
};
Cantilever MakeCantilever(int elements) {
  Cantilever c;
  fe::Mesh& mesh = c.model.mesh;
  mesh.source = "cantilever.bdf";
  const int mat = AddMaterial(mesh, kE, 0.3, kRho);
  fe::BeamSection s;
  s.id = 1;
  s.material = mat;
  s.A = kArea;
  s.Iy = kIy;
  s.Iz = kIz;
  s.J = 2e-9;
  s.nsm = kNsm;
  mesh.beam_sections.push_back(s);
  for (int k = 0; k <= elements; ++k) AddNode(mesh, fe::Vec3(kLength * k / elements, 0.0, 0.0));
  for (int k = 0; k < elements; ++k) AddBeam(mesh, 0, k, k + 1, fe::Vec3(0.0, 1.0, 0.0));
  c.tip = elements;
  c.options.interface_nodes = {c.tip};
  c.options.fixed_nodes = {0};
  // enough fixed-interface modes that the Craig-Bampton truncation error of
  // the four lowest modes stays below 1e-6
  c.options.normal_modes = 60;
  return c;
}

// compares the reduced cantilever's z-bending modes 1..4 with the analytic
// ones (checks only if `expect`) and returns the errors of the terms that
// depend on w, for the convergence study
struct ModeErrors {
  std::array<double, 4> moo1{}, moo2{};
};
ModeErrors CompareWithEulerBernoulli(int elements, bool expect) {
  const Cantilever c = MakeCantilever(elements);
  const ReducedBody body = ReduceCraigBampton(c.model, c.options);
  const InertiaInvariants& inv = body.invariants;
  const int n = inv.n;
  const double m = kMu * kLength;
  ModeErrors out;
  EXPECT_EQ(n, 66);

  // the bending modes along z: uz carries their motion
  std::vector<int> zmodes;
  for (int j = 0; j < n; ++j) {
    double uz = 0.0, all = 0.0;
    for (int k = 0; k <= elements; ++k) {
      const Vec3 u = body.modes.block(6 * k, j, 3, 1);
      uz += u.z() * u.z();
      all += u.squaredNorm();
    }
    if (uz > 0.999 * all) zmodes.push_back(j);
  }
  if (zmodes.size() < 4) {
    ADD_FAILURE() << "fewer than four bending modes along z";
    return out;
  }
  const double published[4] = {0.6131, 0.1883, 0.0647, 0.0331};
  for (int i = 1; i <= 4; ++i) {
    const int j = zmodes[i - 1];
    const CantileverMode e = Mode(i);
    const std::string what = std::to_string(elements) + " elements, z-bending mode " + std::to_string(i);
    // mass-normalized analytic shape, int mu phi^2 = 1, with the FE mode's sign
    const double norm = std::sqrt(kMu * Integrate([&](double x) { return e.Phi(x) * e.Phi(x); }));
    const double sign = (body.modes(6 * c.tip + 2, j) > 0.0) == (e.Phi(kLength) > 0.0) ? 1.0 : -1.0;
    const double p = sign * kMu * Integrate([&](double x) { return e.Phi(x); }) / norm;
    const double px = sign * kMu * Integrate([&](double x) { return x * e.Phi(x); }) / norm;
    // the quadratic term: int mu phi_i phi_k (e_a x e_z).(e_b x e_z) = delta_ik diag(1, 1, 0)
    for (int k = 1; k <= 4; ++k) {
      const Mat3 ref = i == k ? Mat3(Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal()) : Mat3::Zero();
      out.moo2[i - 1] =
          std::max(out.moo2[i - 1], (inv.moo2[j * n + zmodes[k - 1]] - ref).cwiseAbs().maxCoeff());
    }
    // the first-order product of inertia J_xz = -int mu x phi
    out.moo1[i - 1] = std::max(std::abs(inv.moo1[j](0, 2) + px), std::abs(inv.moo1[j](2, 0) + px)) / std::abs(px);
    if (!expect) continue;
    const double f_ref = e.beta * e.beta * std::sqrt(kE * kIy / kMu) / (2.0 * M_PI);
    EXPECT_NEAR(body.frequencies_hz[j], f_ref, 2e-6 * f_ref) << what;
    // modal momentum E^T M h (along z only) and the effective mass
    EXPECT_NEAR(inv.mvw(2, j), p, 2e-6 * std::abs(p)) << what;
    EXPECT_LE(std::abs(inv.mvw(0, j)) + std::abs(inv.mvw(1, j)), 1e-9 * std::abs(p)) << what;
    EXPECT_NEAR(inv.mvw(2, j) * inv.mvw(2, j) / m, published[i - 1], 6e-5) << what;
    // modal angular momentum about the clamp: -int mu x phi about y
    EXPECT_NEAR(inv.mow0(1, j), -px, 2e-6 * std::abs(px)) << what;
    EXPECT_LE(std::abs(inv.mow0(0, j)) + std::abs(inv.mow0(2, j)), 1e-9 * std::abs(px)) << what;
  }
  return out;
}

// the rigid blocks: m, the first moment and the inertia about the clamp of
// the uniform beam, exact for the consistent mass (rotary inertia rho I L
// included)
TEST(ReductionInvariants, CantileverRigidBlocks) {
  const Cantilever c = MakeCantilever(20);
  const InertiaInvariants inv = ReduceCraigBampton(c.model, c.options).invariants;
  const double m = kMu * kLength;
  EXPECT_LE((inv.mvv - m * Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-13 * m);
  const Mat3 s_ref = -m * fe::testing::Skew(Vec3(kLength / 2.0, 0.0, 0.0));
  EXPECT_LE((inv.mvo0 - s_ref).cwiseAbs().maxCoeff(), 1e-13 * m * kLength);
  const Mat3 j_ref = Eigen::Vector3d(kRho * (kIy + kIz) * kLength, m * kLength * kLength / 3.0 + kRho * kIy * kLength,
                                     m * kLength * kLength / 3.0 + kRho * kIz * kLength)
                         .asDiagonal();
  EXPECT_LE((inv.moo0 - j_ref).cwiseAbs().maxCoeff(), 1e-13 * m * kLength * kLength);
}

// the modal momentum and angular momentum (mvw, mow0) against the analytic
// integrals, the effective masses against the published fractions; the
// w-dependent terms (moo1, moo2) converge to the analytic integrals as h^2:
// Omega1 carries the nodes' translations e_a x h with zero rotations, so the
// beam's cubic interpolation of it is exact at the nodes only
TEST(ReductionInvariants, CantileverAgainstEulerBernoulliModes) {
  const ModeErrors coarse = CompareWithEulerBernoulli(50, false);
  const ModeErrors fine = CompareWithEulerBernoulli(100, true);
  for (int i = 0; i < 4; ++i) {
    const std::string what = "z-bending mode " + std::to_string(i + 1);
    EXPECT_LE(fine.moo1[i], 2e-2) << what;
    EXPECT_LE(fine.moo2[i], 3e-3) << what;
    EXPECT_NEAR(coarse.moo1[i] / fine.moo1[i], 4.0, 0.1) << what << ": moo1 not converging as h^2";
    EXPECT_NEAR(coarse.moo2[i] / fine.moo2[i], 4.0, 0.1) << what << ": moo2 not converging as h^2";
  }
}

}  // namespace reduction_invariants_test
}  // namespace flexmb::reduction
