#pragma once
/// \file matrix_test_util.h
/// Helpers for the matrix file tests (Harwell-Boeing, Matrix Market,
/// CalculiX matrix storage, exchange sets): the small matrices of the test
/// data and the bit-for-bit comparison of sparse matrices. Scratch files and
/// bad-input tables: mesh_io_test_util.h.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <random>
#include <utility>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "mesh_io_test_util.h"

namespace flexmb::io::testing {

/// The symmetric positive definite 4 x 4 matrix stored in
/// tests/data/fe/hb/classic_rsa.hb and tests/data/fe/mtx/symmetric.mtx.
inline Eigen::Matrix4d SymmetricTestMatrix() {
  Eigen::Matrix4d a;
  a << 4, -1, 0, 0.5, -1, 4, -1, 0, 0, -1, 4, -1, 0.5, 0, -1, 3;
  return a;
}

/// The symmetric 3 x 3 matrix of whole numbers stored (upper triangle) in
/// tests/data/fe/mtx/integer_upper.mtx.
inline Eigen::Matrix3d IntegerTestMatrix() {
  Eigen::Matrix3d a;
  a << 2000, -1000, 0, -1000, 2000, 0, 0, 0, 1000;
  return a;
}

/// Position (row, column) of the k-th special value of
/// RandomRoundTripMatrix in an n x n matrix (also stored mirrored).
inline std::pair<int, int> RoundTripSpecialPosition(int n, int k) { return {(k * 7 + 3) % n, n - 1 - k % n}; }

/// A random sparse n x n matrix for the round-trip tests of the matrix
/// writers: diagonal `diagonal` + U(-1, 1) (scaled by 10^U(exponents) when
/// `scaled_diagonal`), each lower entry present with probability `density`
/// and of magnitude U(-1, 1) 10^U(+-max_exponent), mirrored (symmetric) or
/// with an independent upper entry; then the `specials` (values that need
/// all 17 significant digits, extremes, subnormals, -0) at pseudo-random
/// symmetric positions, overwriting what is there.
inline fe::SparseMat RandomRoundTripMatrix(int n, unsigned seed, bool symmetric, int max_exponent, double density,
                                           std::initializer_list<double> specials) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-max_exponent, max_exponent);
  std::vector<Eigen::Triplet<double, int>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + u(rng));
    for (int j = 0; j < i; ++j) {
      if (u(rng) > 1.0 - 2.0 * density) {
        const double v = u(rng) * std::pow(10.0, e(rng));
        t.emplace_back(i, j, v);
        t.emplace_back(j, i, symmetric ? v : u(rng));
      }
    }
  }
  int k = 0;
  for (double v : specials) {
    const auto [i, j] = RoundTripSpecialPosition(n, k);
    ++k;
    t.emplace_back(i, j, v);
    if (i != j) t.emplace_back(j, i, v);
  }
  fe::SparseMat A(n, n);
  A.setFromTriplets(t.begin(), t.end(), [](double, double b) { return b; });
  A.makeCompressed();
  return A;
}

/// Same compressed storage: column pointers, row indices and bit-identical values.
inline void ExpectBitIdentical(const fe::SparseMat& a, const fe::SparseMat& b) {
  ASSERT_EQ(a.rows(), b.rows());
  ASSERT_EQ(a.cols(), b.cols());
  ASSERT_EQ(a.nonZeros(), b.nonZeros());
  ASSERT_TRUE(a.isCompressed() && b.isCompressed());
  for (int j = 0; j <= a.cols(); ++j) ASSERT_EQ(a.outerIndexPtr()[j], b.outerIndexPtr()[j]) << "column " << j;
  for (int k = 0; k < a.nonZeros(); ++k) {
    ASSERT_EQ(a.innerIndexPtr()[k], b.innerIndexPtr()[k]) << "entry " << k;
    ASSERT_EQ(std::memcmp(&a.valuePtr()[k], &b.valuePtr()[k], sizeof(double)), 0)
        << "entry " << k << ": " << a.valuePtr()[k] << " vs " << b.valuePtr()[k];
  }
}

}  // namespace flexmb::io::testing
