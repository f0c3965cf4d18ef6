#include "flexmb/fe/sparse_cholesky.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "fe_test_models.h"
#include "flexmb/common/error.h"

namespace flexmb::fe {
namespace {

using testing::AddConstraint;
using testing::Lattice;

// a clamped steel frame: K is positive definite, about 200 DOF
AssembledModel CholeskyClampedFrame() {
  Mesh mesh = Lattice(4, 3, 3, 0.5);
  AddConstraint(mesh, 0, 0b111111);
  AddConstraint(mesh, 1, 0b111111);
  return Assemble(mesh);
}

std::string MessageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const NumericalError& e) {
    return e.what();
  }
  return "";
}

// against Eigen's dense Cholesky of the same matrix
TEST(SparseCholesky, SolvesManyRightHandSidesLikeDenseCholesky) {
  const AssembledModel model = CholeskyClampedFrame();
  const Eigen::MatrixXd dense(model.K);
  const Eigen::Index n = dense.rows();
  SparseCholesky factor;
  factor.Factorize(model.K, "K");
  ASSERT_EQ(factor.rows(), n);
  EXPECT_GE(factor.FactorNonZeros(), 0.5 * (model.K.nonZeros() + n));
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(n, 7);
  const Eigen::MatrixXd x = factor.Solve(b);
  const Eigen::MatrixXd ref = dense.llt().solve(b);
  EXPECT_LT((x - ref).norm(), 1e-10 * ref.norm());
  // and the residual itself
  EXPECT_LT((dense * x - b).norm(), 1e-10 * b.norm());
}

// A = P^T L L^T P: the triangular and permutation pieces compose to A^{-1},
// single-vector and block versions agree
TEST(SparseCholesky, TriangularSolvesComposeToTheInverse) {
  const AssembledModel model = CholeskyClampedFrame();
  const Eigen::Index n = model.K.rows();
  SparseCholesky factor;
  factor.Factorize(model.K, "K");
  const int* perm = factor.Permutation();
  ASSERT_NE(perm, nullptr);
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(n, 3);
  Eigen::MatrixXd pb(n, 3);
  for (Eigen::Index k = 0; k < n; ++k) pb.row(k) = b.row(perm[k]);
  const Eigen::MatrixXd z = factor.SolveLt(factor.SolveL(pb));
  Eigen::MatrixXd x(n, 3);
  for (Eigen::Index k = 0; k < n; ++k) x.row(perm[k]) = z.row(k);
  const Eigen::MatrixXd ref = factor.Solve(b);
  EXPECT_LT((x - ref).norm(), 1e-12 * ref.norm());
  for (int j = 0; j < 3; ++j) {
    Eigen::VectorXd y(n), w(n);
    factor.SolveL(pb.col(j).data(), y.data());
    factor.SolveLt(y.data(), w.data());
    EXPECT_LT((w - z.col(j)).norm(), 1e-14 * z.col(j).norm());
    // in place (x and y may alias)
    y = pb.col(j);
    factor.SolveL(y.data(), y.data());
    factor.SolveLt(y.data(), y.data());
    EXPECT_LT((y - z.col(j)).norm(), 1e-14 * z.col(j).norm());
  }
}

// the symbolic analysis is reused for a matrix of the same pattern and
// redone for another one; both give correct solves
TEST(SparseCholesky, RefactorizesNewValuesAndNewPatterns) {
  const AssembledModel model = CholeskyClampedFrame();
  SparseCholesky factor;
  factor.Factorize(model.K, "K");
  const SparseMat shifted = model.K + 1e3 * model.M;
  factor.Factorize(shifted, "K + 1e3 M");
  const Eigen::VectorXd b = Eigen::VectorXd::Random(model.K.rows());
  const Eigen::VectorXd x = factor.Solve(b);
  EXPECT_LT((shifted * x - b).norm(), 1e-10 * b.norm());

  Mesh small = Lattice(2, 2, 2, 0.5);
  AddConstraint(small, 0, 0b111111);
  const AssembledModel other = Assemble(small);
  factor.Factorize(other.K, "K of another model");
  const Eigen::VectorXd c = Eigen::VectorXd::Random(other.K.rows());
  EXPECT_LT((other.K * factor.Solve(c) - c).norm(), 1e-10 * c.norm());
}

// a negative stiffness fails exactly at its pivot: the message names the
// matrix and the DOF through the describer
TEST(SparseCholesky, NotPositiveDefiniteNamesTheDof) {
  const AssembledModel model = CholeskyClampedFrame();
  SparseMat k = model.K;
  const int bad = 17;
  k.coeffRef(bad, bad) = -1.0;
  SparseCholesky factor;
  const std::string msg =
      MessageOf([&] { factor.Factorize(k, "K_test", [](int j) { return "dof #" + std::to_string(j) + "#"; }); });
  EXPECT_NE(msg.find("K_test is not positive definite"), std::string::npos) << msg;
  EXPECT_NE(msg.find("dof #"), std::string::npos) << msg;
  EXPECT_EQ(factor.rows(), 0);
  EXPECT_THROW(factor.Solve(Eigen::MatrixXd::Ones(k.rows(), 1)), NumericalError);
}

// a DOF without any stiffness (zero row and column): the factorization
// fails exactly at its pivot, and the message names it
TEST(SparseCholesky, ZeroColumnIsNamed) {
  const AssembledModel model = CholeskyClampedFrame();
  SparseMat k = model.K;
  const int bad = 40;
  for (SparseMat::InnerIterator it(k, bad); it; ++it) it.valueRef() = 0.0;
  for (int j = 0; j < k.outerSize(); ++j) {
    for (SparseMat::InnerIterator it(k, j); it; ++it) {
      if (it.row() == bad) it.valueRef() = 0.0;
    }
  }
  SparseCholesky factor;
  const std::string msg = MessageOf([&] { factor.Factorize(k, "K", [](int j) { return "<" + std::to_string(j) + ">"; }); });
  EXPECT_NE(msg.find("<40>"), std::string::npos) << msg;
}

// a free-free frame: K is singular (rigid motions) but round-off keeps the
// pivots positive; the pivot test catches it and names a DOF
TEST(SparseCholesky, RoundOffSingularMatrixIsCaught) {
  const AssembledModel model = Assemble(Lattice(4, 3, 3, 0.5));
  SparseCholesky factor;
  const std::string msg = MessageOf([&] { factor.Factorize(model.K, "K_free", [](int j) { return "DOF" + std::to_string(j); }); });
  EXPECT_NE(msg.find("K_free"), std::string::npos) << msg;
  EXPECT_NE(msg.find("DOF"), std::string::npos) << msg;
  // the same model with a small shift is fine
  EXPECT_NO_THROW(factor.Factorize(SparseMat(model.K + 1.0 * model.M), "K + M"));
}

TEST(SparseCholesky, NonFiniteAndMalformedInput) {
  AssembledModel model = CholeskyClampedFrame();
  SparseCholesky factor;
  model.K.coeffRef(3, 3) = std::numeric_limits<double>::quiet_NaN();
  const std::string msg = MessageOf([&] { factor.Factorize(model.K, "K", [](int j) { return "<" + std::to_string(j) + ">"; }); });
  EXPECT_NE(msg.find("non-finite"), std::string::npos) << msg;
  EXPECT_NE(msg.find("<3>"), std::string::npos) << msg;
  EXPECT_THROW(factor.Factorize(SparseMat(3, 4), "K"), NumericalError);
  EXPECT_THROW(factor.Factorize(SparseMat(0, 0), "K"), NumericalError);
}

}  // namespace
}  // namespace flexmb::fe
