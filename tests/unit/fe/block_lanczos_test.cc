#include "flexmb/fe/block_lanczos.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "fe_test_models.h"
#include "flexmb/common/error.h"

namespace flexmb::fe {
namespace {

using testing::AddConstraint;
using testing::Lattice;

AssembledModel ClampedFrame(int nx = 4) {
  Mesh mesh = Lattice(nx, 3, 3, 0.5);
  AddConstraint(mesh, 0, 0b111111);
  AddConstraint(mesh, 1, 0b111111);
  return Assemble(mesh);
}

// reference: Eigen's dense generalized eigensolver
Eigen::VectorXd DenseHz(const AssembledModel& model, int count) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense{Eigen::MatrixXd(model.K), Eigen::MatrixXd(model.M)};
  Eigen::VectorXd f(count);
  for (int j = 0; j < count; ++j) {
    const double l = dense.eigenvalues()[j];
    f[j] = std::copysign(std::sqrt(std::abs(l)), l) / (2.0 * M_PI);
  }
  return f;
}

void ExpectModes(const AssembledModel& model, const ModalResult& r, const Eigen::VectorXd& ref, double tol) {
  const int n = static_cast<int>(ref.size());
  ASSERT_EQ(r.frequencies_hz.size(), n);
  for (int j = 0; j < n; ++j) EXPECT_NEAR(r.frequencies_hz[j], ref[j], tol * std::abs(ref[n - 1])) << "mode " << j + 1;
  const Eigen::MatrixXd gram = r.modes.transpose() * (model.M * r.modes);
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(BlockLanczos, ClampedFrameMatchesDenseAndSpectra) {
  const AssembledModel model = ClampedFrame();
  SparseCholesky factor;
  factor.Factorize(model.K, "K");
  BlockLanczosOptions options;
  options.count = 12;
  const ModalResult r = SolveModesBlockLanczos(model.K, model.M, factor, 0.0, options);
  ExpectModes(model, r, DenseHz(model, 12), 1e-10);
  const ModalResult s = SolveModesFactorized(model.K, model.M, factor, 0.0, 12);
  for (int j = 0; j < 12; ++j) EXPECT_NEAR(r.frequencies_hz[j], s.frequencies_hz[j], 1e-10 * s.frequencies_hz[11]);
  // each mode satisfies K phi = omega^2 M phi
  for (int j = 0; j < 12; ++j) {
    const double w2 = std::pow(2.0 * M_PI * r.frequencies_hz[j], 2);
    const Eigen::VectorXd kphi = model.K * r.modes.col(j);
    EXPECT_LT((kphi - w2 * (model.M * r.modes.col(j))).norm(), 1e-8 * kphi.norm()) << "mode " << j + 1;
  }
}

// small blocks and a small basis force thick restarts: same answer
TEST(BlockLanczos, ThickRestartsGiveTheSameModes) {
  const AssembledModel model = ClampedFrame(6);
  SparseCholesky factor;
  factor.Factorize(model.K, "K");
  BlockLanczosOptions options;
  options.count = 10;
  options.block_size = 2;
  options.max_basis = 16;
  ExpectModes(model, SolveModesBlockLanczos(model.K, model.M, factor, 0.0, options), DenseHz(model, 10), 1e-9);
}

// a free-free frame with a negative shift: the six rigid modes come first
TEST(BlockLanczos, FreeFrameWithShift) {
  const AssembledModel model = Assemble(Lattice(4, 3, 3, 0.5));
  const double sigma = -50.0;
  SparseCholesky factor;
  factor.Factorize(SparseMat(model.K - sigma * model.M), "K - sigma M");
  BlockLanczosOptions options;
  options.count = 10;
  const ModalResult r = SolveModesBlockLanczos(model.K, model.M, factor, sigma, options);
  const Eigen::VectorXd ref = DenseHz(model, 10);
  for (int j = 0; j < 6; ++j) EXPECT_LT(std::abs(r.frequencies_hz[j]), 1e-4 * ref[6]);
  for (int j = 6; j < 10; ++j) EXPECT_NEAR(r.frequencies_hz[j], ref[j], 1e-9 * ref[9]);
}

// nearly all modes of a small problem: the Krylov space fills the whole space
TEST(BlockLanczos, AlmostAllModesOfASmallProblem) {
  Mesh mesh = Lattice(2, 2, 1, 0.5, false);
  AddConstraint(mesh, 0, 0b111111);
  const AssembledModel model = Assemble(mesh);
  const int n = model.dofs.n_free;
  SparseCholesky factor;
  factor.Factorize(model.K, "K");
  BlockLanczosOptions options;
  options.count = n - 1;
  ExpectModes(model, SolveModesBlockLanczos(model.K, model.M, factor, 0.0, options), DenseHz(model, n - 1), 1e-9);
}

TEST(BlockLanczos, BadRequestsAndMasslessModes) {
  const AssembledModel model = ClampedFrame();
  SparseCholesky factor;
  factor.Factorize(model.K, "K");
  BlockLanczosOptions options;
  options.count = static_cast<int>(model.K.rows());
  EXPECT_THROW(SolveModesBlockLanczos(model.K, model.M, factor, 0.0, options), InputError);
  options.count = 0;
  EXPECT_THROW(SolveModesBlockLanczos(model.K, model.M, factor, 0.0, options), InputError);
  options.count = 3;
  EXPECT_THROW(SolveModesBlockLanczos(model.K, model.M, factor, 1.0, options), InputError);
  // a mass matrix with only two non-zero diagonal entries has two modes with mass
  SparseMat m(model.M.rows(), model.M.cols());
  m.insert(0, 0) = 1.0;
  m.insert(5, 5) = 1.0;
  EXPECT_THROW(SolveModesBlockLanczos(model.K, m, factor, 0.0, options), NumericalError);
}

}  // namespace
}  // namespace flexmb::fe
