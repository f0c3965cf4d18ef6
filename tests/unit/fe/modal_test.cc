#include "flexmb/fe/modal.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "tests/unit/fe/fe_test_models.h"
#include "flexmb/common/error.h"

namespace flexmb::fe {
namespace {

using testing::AddConstraint;
using testing::Lattice;
using testing::SpringChain;

// clamped-free chain of N equal masses m and springs k:
// omega_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2N + 1)))
double ChainOmega(int j, int n, double k, double m) {
  return 2.0 * std::sqrt(k / m) * std::sin((2.0 * j - 1.0) * M_PI / (2.0 * (2.0 * n + 1.0)));
}

// Expects the rigid-body vectors of the free mesh to lie in the span of the
// first six (M-orthonormal) columns of phi.
void ExpectRigidModesSpanned(const Mesh& mesh, const AssembledModel& model, const Eigen::MatrixXd& phi,
                             double tolerance = 1e-6) {
  Eigen::MatrixXd rigid = Eigen::MatrixXd::Zero(model.dofs.n_free, 6);
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    const Vec3& x = mesh.nodes[n].x;
    for (int c = 0; c < 6; ++c) {
      const int f = model.dofs.free[n][c];
      if (f < 0) continue;
      for (int a = 0; a < 6; ++a) {
        Vec3 u = Vec3::Zero(), th = Vec3::Zero();
        (a < 3 ? u : th)[a % 3] = 1.0;
        const Vec3 ux = u + th.cross(x);
        rigid(f, a) = c < 3 ? ux[c] : th[c - 3];
      }
    }
  }
  const Eigen::MatrixXd p6 = phi.leftCols(6);
  const Eigen::MatrixXd residual = rigid - p6 * (p6.transpose() * (model.M * rigid));
  EXPECT_LT(residual.norm(), tolerance * rigid.norm());
}

TEST(Modal, SpringChainMatchesAnalyticFrequencies) {
  const double k = 3.0e5, m = 2.5;
  for (int n : {3, 40}) {
    const Mesh mesh = SpringChain(n, k, m);
    const AssembledModel model = Assemble(mesh);
    ASSERT_EQ(model.dofs.n_free, n);
    ModalOptions options;
    options.count = std::min(10, n - 1);
    const ModalResult r = SolveModes(model, options);
    ASSERT_EQ(r.frequencies_hz.size(), options.count);
    for (int j = 1; j <= options.count; ++j) {
      const double ref = ChainOmega(j, n, k, m) / (2.0 * M_PI);
      EXPECT_NEAR(r.frequencies_hz[j - 1], ref, 1e-9 * ref) << "N = " << n << ", mode " << j;
    }
  }
}

// against a dense generalized eigensolver on a small clamped frame
TEST(Modal, ClampedFrameMatchesDenseSolver) {
  Mesh mesh = Lattice(3, 2, 2, 0.4);
  AddConstraint(mesh, 0, 0b111111);
  AddConstraint(mesh, 1, 0b111111);
  const AssembledModel model = Assemble(mesh);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense{Eigen::MatrixXd(model.K), Eigen::MatrixXd(model.M)};
  ModalOptions options;
  options.count = 12;
  const ModalResult r = SolveModes(model, options);
  for (int j = 0; j < options.count; ++j) {
    const double ref = std::sqrt(dense.eigenvalues()[j]) / (2.0 * M_PI);
    EXPECT_NEAR(r.frequencies_hz[j], ref, 1e-9 * ref) << "mode " << j + 1;
  }
  // an explicit shift gives the same answer
  options.shift = -10.0;
  const ModalResult s = SolveModes(model, options);
  for (int j = 0; j < options.count; ++j) {
    EXPECT_NEAR(s.frequencies_hz[j], r.frequencies_hz[j], 1e-9 * r.frequencies_hz[j]);
  }
}

// a free-free frame: six rigid modes near 0 first, spanning rigid motion;
// modes M-orthonormal and satisfying K phi = omega^2 M phi
TEST(Modal, FreeFreeFrameHasSixRigidModesFirst) {
  const Mesh mesh = Lattice(4, 3, 3, 0.5);
  const AssembledModel model = Assemble(mesh);
  ModalOptions options;
  options.count = 12;
  const ModalResult r = SolveModes(model, options);
  const double f7 = r.frequencies_hz[6];
  EXPECT_GT(f7, 1.0);
  for (int j = 0; j < 6; ++j) EXPECT_LT(std::abs(r.frequencies_hz[j]), 1e-4 * f7) << "mode " << j + 1;
  for (int j = 7; j < options.count; ++j) EXPECT_GE(r.frequencies_hz[j], r.frequencies_hz[j - 1]);

  const Eigen::MatrixXd& phi = r.modes;
  const Eigen::MatrixXd gram = phi.transpose() * (model.M * phi);
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(options.count, options.count)).cwiseAbs().maxCoeff(), 1e-10);
  for (int j = 6; j < options.count; ++j) {
    const double w2 = std::pow(2.0 * M_PI * r.frequencies_hz[j], 2);
    const Eigen::VectorXd kphi = model.K * phi.col(j);
    EXPECT_LT((kphi - w2 * (model.M * phi.col(j))).norm(), 1e-8 * kphi.norm()) << "mode " << j + 1;
  }
  // rigid-body vectors lie in the span of the first six modes
  ExpectRigidModesSpanned(mesh, model, phi);
}

TEST(Modal, BadRequests) {
  const Mesh mesh = SpringChain(4, 1.0e4, 1.0);
  const AssembledModel model = Assemble(mesh);
  ModalOptions options;
  options.count = 4;
  EXPECT_THROW(SolveModes(model, options), InputError);
  options.count = 0;
  EXPECT_THROW(SolveModes(model, options), InputError);
  options.count = 2;
  options.shift = 5.0;
  EXPECT_THROW(SolveModes(model, options), InputError);
}

// massless bars with one point mass: rotations about that mass have neither
// stiffness nor mass, K - sigma M is singular
TEST(Modal, MasslessMechanismIsANumericalError) {
  Mesh mesh = Lattice(3, 2, 1, 0.5, false);
  mesh.materials[0].rho = 0.0;
  testing::AddPointMass(mesh, 0, 1.0);
  const AssembledModel model = Assemble(mesh);
  ModalOptions options;
  options.count = 3;
  EXPECT_THROW(SolveModes(model, options), NumericalError);
}

// A slender free-free steel bar of thousands of beam elements: the automatic
// shift must lie close below the first flexible modes, or the six rigid
// modes are not separated from them (a shift scaled by the element
// frequencies lost two rigid modes at 2000 elements and failed at 5000).
// Reference: Euler-Bernoulli free-free bending, beta L = 4.730040745
// (Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1);
// shear and rotary inertia change it by O((r/L)^2) = 2.5e-5 here.
TEST(Modal, SlenderFreeFreeBarKeepsItsSixRigidModes) {
  const double length = 2.0, r = 0.01, E = 2.1e11, rho = 7850.0;
  const double area = M_PI * r * r, inertia = M_PI * std::pow(r, 4) / 4.0;
  const double beta_l = 4.730040745;
  const double f_ref = beta_l * beta_l / (2.0 * M_PI * length * length) * std::sqrt(E * inertia / (rho * area));
  for (int n : {2000, 5000}) {
    Mesh mesh;
    const int mat = testing::AddMaterial(mesh, E, 0.3, rho);
    const int sec = testing::AddRoundBar(mesh, mat, r);
    for (int i = 0; i <= n; ++i) {
      Node node;
      node.id = i + 1;
      node.x = Vec3(length * i / n, 0.0, 0.0);
      mesh.nodes.push_back(node);
    }
    mesh.IndexNodes();
    for (int i = 0; i < n; ++i) testing::AddBeam(mesh, sec, i, i + 1, Vec3::UnitZ());
    const AssembledModel model = Assemble(mesh);
    ModalOptions options;
    options.count = 8;
    const ModalResult res = SolveModes(model, options);
    // the rigid modes' frequencies are round-off, sqrt(eps * lambda_max) / 2 pi ~ 0.3 Hz for the
    // 0.4 mm elements (lambda_max ~ 3 G / (rho h^2) of torsion); what matters is their span
    for (int j = 0; j < 6; ++j) EXPECT_LT(std::abs(res.frequencies_hz[j]), 0.05 * f_ref) << n << " elements, mode " << j + 1;
    // The span is only as good as K's round-off allows: a perturbation of eps * lambda_max
    // (mass-normalized) tilts the rigid subspace by ~ eps * lambda_max / lambda_7 (Davis-Kahan),
    // with lambda_max ~ 1e15 .. 1e16 s^-2 for 1 mm and 0.4 mm elements: measured 6.5e-6 at 2000
    // and 1.2e-3 at 5000 elements (Spectra and block Lanczos alike). A lost rigid mode leaves
    // a residual of order 1.
    ExpectRigidModesSpanned(mesh, model, res.modes, 1e-2);
    // the two bending planes of the round bar
    for (int j = 6; j < 8; ++j) EXPECT_NEAR(res.frequencies_hz[j], f_ref, 1e-3 * f_ref) << n << " elements, mode " << j + 1;
  }
}

}  // namespace
}  // namespace flexmb::fe
