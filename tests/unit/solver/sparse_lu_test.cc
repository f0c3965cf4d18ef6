// SparseLu's dense path (large, mostly dense matrices) against KLU on the
// same matrices: equal solutions on a random well-conditioned system (and the
// residual of both at round-off), the same singular column on a matrix with a
// zero column, and the dependent column found on a matrix whose column is a
// combination of earlier ones; on a large matrix that needs row exchanges,
// the backward error of the dense path's solution.

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "flexmb/solver/sparse_lu.h"

namespace flexmb {
namespace {

// random dense n x n with a dominant diagonal (well conditioned), every entry
// stored
SparseMat RandomDense(int n, unsigned seed, Eigen::MatrixXd& dense) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  dense.resize(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) dense(i, j) = u(gen) + (i == j ? 2.0 * n : 0.0);
  SparseMat A(n, n);
  A.reserve(Eigen::VectorXi::Constant(n, n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) A.insert(i, j) = dense(i, j);
  A.makeCompressed();
  return A;
}

void SetColumn(SparseMat& A, int j, const Eigen::VectorXd& c) {
  for (SparseMat::InnerIterator it(A, j); it; ++it) it.valueRef() = c(it.row());
}

TEST(SparseLu, DensePathSolvesLikeKlu) {
  const int n = 90;
  Eigen::MatrixXd D;
  const SparseMat A = RandomDense(n, 7, D);
  SparseLu dense, klu(SparseLu::Path::kKlu);
  ASSERT_TRUE(dense.Factorize(A));
  ASSERT_TRUE(klu.Factorize(A));
  EXPECT_TRUE(dense.dense());
  EXPECT_FALSE(klu.dense());
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int rep = 0; rep < 2; ++rep) {
    VecX b(n);
    for (int i = 0; i < n; ++i) b(i) = u(gen);
    VecX x1 = b, x2 = b;
    dense.Solve(x1);
    klu.Solve(x2);
    EXPECT_LT((x1 - x2).norm(), 1e-13 * x2.norm());
    EXPECT_LT((D * x1 - b).norm(), 1e-13 * b.norm());
    EXPECT_LT((D * x2 - b).norm(), 1e-13 * b.norm());
  }
  // both condition estimates are min/max |u_kk|: diagonal dominance keeps
  // the pivots near 2n
  EXPECT_GT(dense.rcond(), 0.5);
  EXPECT_NEAR(dense.rcond(), klu.rcond(), 0.1);
  // a second factorization of new values with the same pattern
  SparseMat A2 = A;
  for (int k = 0; k < A2.nonZeros(); ++k) A2.valuePtr()[k] *= 1.5;
  ASSERT_TRUE(dense.Factorize(A2));
  VecX b = VecX::Ones(n), x = b;
  dense.Solve(x);
  EXPECT_LT((1.5 * D * x - b).norm(), 1e-13 * b.norm());
}

TEST(SparseLu, DensePathReportsTheSingularColumnLikeKlu) {
  const int n = 80, col = 37;
  Eigen::MatrixXd D;
  SparseMat A = RandomDense(n, 11, D);
  SetColumn(A, col, VecX::Zero(n));  // stored, numerically zero
  SparseLu dense, klu(SparseLu::Path::kKlu);
  EXPECT_FALSE(dense.Factorize(A));
  EXPECT_FALSE(klu.Factorize(A));
  EXPECT_TRUE(dense.dense());
  EXPECT_EQ(klu.singular_column(), col);
  EXPECT_EQ(dense.singular_column(), col);
  // a column combining earlier ones: its pivot is round-off
  SetColumn(A, col, 0.7 * D.col(3) - 1.3 * D.col(20) + D.col(36));
  EXPECT_FALSE(dense.Factorize(A));
  EXPECT_EQ(dense.singular_column(), col);
  // restored, it factorizes again
  SetColumn(A, col, D.col(col));
  EXPECT_TRUE(dense.Factorize(A));
  EXPECT_EQ(dense.singular_column(), -1);
}

TEST(SparseLu, DensePathRefusesNaNAndInfinity) {
  // a NaN or an infinite entry (a force element gone bad) must not give a
  // factorization: singular, with a column named, like KLU
  const int n = 70;
  Eigen::MatrixXd D;
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    SparseMat A = RandomDense(n, 13, D);
    A.coeffRef(40, 25) = bad;
    SparseLu dense;
    EXPECT_FALSE(dense.Factorize(A)) << bad;
    EXPECT_TRUE(dense.dense());
    EXPECT_GE(dense.singular_column(), 0) << bad;
    EXPECT_LT(dense.singular_column(), n) << bad;
    EXPECT_EQ(dense.rcond(), 0.0) << bad;
  }
}

TEST(SparseLu, DensePathPivotsOnLargeMatrices) {
  // no dominant diagonal (row exchanges needed) and n = 530: more than one
  // panel and more than one trailing-product chunk of the dense LU; reference:
  // the normwise backward error of the solution (round-off for a stable LU)
  const int n = 530;
  std::mt19937 gen(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd D(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) D(i, j) = u(gen);
  D(0, 0) = 0.0;  // the first pivot must come from another row
  SparseMat A(n, n);
  A.reserve(Eigen::VectorXi::Constant(n, n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) A.insert(i, j) = D(i, j);
  A.makeCompressed();
  SparseLu lu;
  ASSERT_TRUE(lu.Factorize(A));
  ASSERT_TRUE(lu.dense());
  VecX b(n);
  for (int i = 0; i < n; ++i) b(i) = u(gen);
  VecX x = b;
  lu.Solve(x);
  const double anorm = D.cwiseAbs().rowwise().sum().maxCoeff();
  EXPECT_LT((D * x - b).lpNorm<Eigen::Infinity>(), 1e-13 * anorm * x.lpNorm<Eigen::Infinity>());
}

TEST(SparseLu, SmallOrSparseMatricesStayOnKlu) {
  Eigen::MatrixXd D;
  SparseLu small;
  ASSERT_TRUE(small.Factorize(RandomDense(SparseLu::kDenseMinRows - 1, 5, D)));
  EXPECT_FALSE(small.dense());
  // tridiagonal 200 x 200: fill far below kDenseMinFill
  const int n = 200;
  SparseMat T(n, n);
  for (int i = 0; i < n; ++i) {
    T.insert(i, i) = 4.0;
    if (i > 0) T.insert(i, i - 1) = -1.0;
    if (i + 1 < n) T.insert(i, i + 1) = -1.0;
  }
  T.makeCompressed();
  SparseLu sparse;
  ASSERT_TRUE(sparse.Factorize(T));
  EXPECT_FALSE(sparse.dense());
}

}  // namespace
}  // namespace flexmb
