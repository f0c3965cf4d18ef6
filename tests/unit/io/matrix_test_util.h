#pragma once
/// \file matrix_test_util.h
/// Helpers for the matrix file tests (Harwell-Boeing, Matrix Market,
/// CalculiX matrix storage, exchange sets): the small matrices of the test
/// data and the bit-for-bit comparison of sparse matrices. Scratch files and
/// bad-input tables: mesh_io_test_util.h.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstring>

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
